"""The README's usage example runs as printed (users copy it first)."""
import re
from pathlib import Path

README = Path(__file__).resolve().parent.parent / "README.md"


def test_readme_python_example_runs():
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(), flags=re.S)
    assert blocks, "README has no python example"
    namespace = {}
    exec(compile(blocks[0], "README.md", "exec"), namespace)
    lyap = namespace["lyap"]
    assert len(lyap.exponents) == 2 and all(e > 0 for e in lyap.exponents)
    assert namespace["traj"].theta.shape[1] == 4


def test_readme_notebook_example_runs(tmp_path, monkeypatch):
    """The second example (events, dense output, plots, save/load) runs after the first."""
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(), flags=re.S)
    monkeypatch.chdir(tmp_path)
    namespace = {}
    exec(compile(blocks[0], "README.md", "exec"), namespace)
    exec(compile(blocks[1], "README.md", "exec"), namespace)
    res = namespace["res"]
    assert len(res.t_events[0]) > 100 and res.sol(12.5).shape == (6,)
    assert (tmp_path / "lyap.nc").exists()
    ds = namespace["ds"]                    # the file, read without charts
    assert int(ds.attrs["params_n"]) == 4 and ds.attrs["Conventions"].startswith("CF-")
    ds.close()


def test_every_package_folder_is_installed():
    """pyproject.toml lists packages explicitly (charts.generated lives in generated/): a new
    subpackage missing from the list would be absent from a non-editable install."""
    try:
        import tomllib
    except ModuleNotFoundError:  # Python 3.10
        import tomli as tomllib
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    listed = set(tomllib.loads((root / "pyproject.toml").read_text())["tool"]["setuptools"]["packages"])
    found = {".".join(p.parent.relative_to(root).parts) for p in (root / "charts").rglob("*.py")
             if "__pycache__" not in p.parts}
    found |= {".".join(p.parent.relative_to(root).parts) for p in (root / "charts").rglob("*.toml")}
    assert found <= listed, sorted(found - listed)
