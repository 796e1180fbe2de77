"""Which code made a result: ``charts.version.source_version`` changes whenever the code does
(the git commit in a checkout, with ``.dirty`` for changed files; a digest of the source
files elsewhere)."""
import re
import shutil
import subprocess
import sys

import pytest

import charts
from charts import version


def test_the_release_with_the_commit_or_the_source_digest():
    v = version.source_version()
    assert v.startswith(charts.__version__ + "+")
    assert re.fullmatch(r"[0-9.]+\+(g[0-9a-f]{7,}(\.dirty)?|src\.[0-9a-f]{8})", v), v
    assert re.fullmatch(r"[0-9a-f]{8}", version.source_digest())


def test_the_digest_changes_with_any_source_file(tmp_path):
    """A copy of the package outside git: its version names the digest of its files, and an
    edit of one file gives another."""
    root = tmp_path / "copy"
    shutil.copytree(version._PACKAGE, root / "charts",
                    ignore=shutil.ignore_patterns("__pycache__", "*.nb*"))
    code = "import charts.version as v; print(v.source_version())"

    def run():
        r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                           cwd=root, timeout=120)
        assert r.returncode == 0, r.stderr
        return r.stdout.strip()

    first = run()
    assert re.fullmatch(r"[0-9.]+\+src\.[0-9a-f]{8}", first), first
    assert run() == first
    with open(root / "charts" / "io" / "atomic.py", "a") as f:
        f.write("\n# an edit\n")
    assert run() != first


@pytest.mark.skipif(shutil.which("git") is None, reason="needs git")
def test_a_checkout_names_its_commit(tmp_path):
    """The package in a git repository of its own: the commit, then ``.dirty`` once a file
    of the package changes."""
    root = tmp_path / "repo"
    shutil.copytree(version._PACKAGE, root / "charts",
                    ignore=shutil.ignore_patterns("__pycache__", "*.nb*"))
    git = ["git", "-C", str(root), "-c", "user.email=t@t", "-c", "user.name=t"]
    subprocess.run(git[:3] + ["init", "-q"], check=True)
    subprocess.run(git + ["add", "-A"], check=True)
    subprocess.run(git + ["commit", "-qm", "x"], check=True)
    head = subprocess.run(git[:3] + ["rev-parse", "--short=7", "HEAD"], capture_output=True,
                          text=True, check=True).stdout.strip()
    code = "import charts.version as v; print(v.source_version())"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=root,
                         timeout=120).stdout.strip()
    assert out == f"{charts.__version__}+g{head}"
    with open(root / "charts" / "io" / "atomic.py", "a") as f:
        f.write("\n# an edit\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=root,
                         timeout=120).stdout.strip()
    assert out == f"{charts.__version__}+g{head}.dirty"
