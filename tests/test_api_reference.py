"""docs/api.md is written from the docstrings by scripts/api_reference.py and never edited by
hand: it must equal what the script writes now (else: run the script)."""
import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _script():
    spec = importlib.util.spec_from_file_location("api_reference", ROOT / "scripts" / "api_reference.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_api_reference_is_current():
    text = _script().render()
    current = (ROOT / "docs" / "api.md").read_text(encoding="utf-8")
    assert current == text, "docs/api.md is stale: run python scripts/api_reference.py"


def test_the_reference_covers_every_public_name_with_its_signature():
    import charts
    text = (ROOT / "docs" / "api.md").read_text(encoding="utf-8")
    for name in charts.__all__:
        assert f"`{name}(" in text or f"`{name}`" in text, name
    assert "- `statistics(variant='restricted', small=0.05)`" in text     # methods listed
