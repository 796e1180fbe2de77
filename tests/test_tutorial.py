"""docs/tutorial.md runs as printed: its Python blocks in order (each after the ones before, as
a reader pastes them), and its scene file validates."""
import re
from pathlib import Path

TUTORIAL = Path(__file__).resolve().parents[1] / "docs" / "tutorial.md"


def test_tutorial_python_blocks_run_in_order(tmp_path, monkeypatch):
    blocks = re.findall(r"```python\n(.*?)```", TUTORIAL.read_text(encoding="utf-8"), flags=re.S)
    assert len(blocks) >= 2
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for i, block in enumerate(blocks):
        exec(compile(block, f"tutorial.md, python block {i + 1}", "exec"), namespace)
    lyap = namespace["lyap"]
    assert len(lyap.exponents) == 2 and all(e > 0 for e in lyap.exponents)
    assert namespace["again"] == lyap and (tmp_path / "lyap-n4.nc").exists()


def test_tutorial_scene_validates(tmp_path):
    import charts
    (toml,) = re.findall(r"```toml\n(.*?)```", TUTORIAL.read_text(encoding="utf-8"), flags=re.S)
    path = tmp_path / "heavy.toml"
    path.write_text(toml, encoding="utf-8")
    scene = charts.load_scene(path)
    assert scene.system["masses"] == [1, 1, 1, 2]
    assert set(scene.effects) == {"lyapunov", "curvature"}
