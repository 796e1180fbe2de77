"""What every refusal of the command line must look like (tests/test_cli_reliability.py,
tests/test_force_lock.py)."""


def one_line_error(capsys, code, status):
    """The stderr of a command that exited with ``code``: it must be ``status`` and one line
    ``charts: error: …`` without a traceback; returns that line."""
    err = capsys.readouterr().err.strip()
    assert code == status, err
    assert err.startswith("charts: error: ") and "\n" not in err and "Traceback" not in err
    return err
