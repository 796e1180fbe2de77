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
