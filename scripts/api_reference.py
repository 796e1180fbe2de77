"""Write docs/api.md: the reference of every public name of ``charts`` (``charts.__all__``),
its signature and its docstring, for classes also their public methods and properties, in
the order of ``charts._HOMES`` (grouped by the module each name lives in).

    python scripts/api_reference.py            # rewrite docs/api.md
    python scripts/api_reference.py --check    # exit 1 when docs/api.md is stale

tests/test_api_reference.py fails when the file is stale; it is never edited by hand.
"""
from __future__ import annotations

import argparse
import inspect
import sys
from pathlib import Path

import charts

OUT = Path(__file__).resolve().parents[1] / "docs" / "api.md"
HEADER = """# API reference

Written by `python scripts/api_reference.py` from the docstrings; do not edit by hand
(tests/test_api_reference.py fails when it is stale). Every name below is importable as
`charts.NAME`; the module in each heading is where it lives. The narrative is in the other
pages of docs/; the equations cited are the paper's.
"""


def _doc(obj) -> str:
    doc = inspect.getdoc(obj) or "(no docstring)"
    return "\n".join(line.rstrip() for line in doc.splitlines())


def _signature(obj) -> str:
    try:
        return str(inspect.signature(obj))
    except (TypeError, ValueError):
        return "(...)"


def _members(cls):
    """(name, kind, object) of the class's public methods and properties, its own and those
    of its bases within the package, in definition order."""
    seen, out = set(), []
    for klass in cls.__mro__:
        if not klass.__module__.startswith("charts"):
            continue
        for name, value in vars(klass).items():
            if name.startswith("_") or name in seen:
                continue
            seen.add(name)
            if isinstance(value, property):
                out.append((name, "property", value))
            elif isinstance(value, (classmethod, staticmethod)):
                out.append((name, "classmethod" if isinstance(value, classmethod) else
                            "staticmethod", value.__func__))
            elif inspect.isfunction(value):
                out.append((name, "method", value))
    return out


def _entry(name, obj) -> list[str]:
    if inspect.isclass(obj):
        if issubclass(obj, BaseException):
            return [f"### exception `{name}`", "", _doc(obj), ""]
        lines = [f"### class `{name}{_signature(obj)}`", "", _doc(obj), ""]
        for mname, kind, member in _members(obj):
            sig = "" if kind == "property" else _signature(member)
            if kind == "method" and sig.startswith("(self, "):
                sig = "(" + sig[len("(self, "):]
            elif kind == "method" and sig.startswith("(self)"):
                sig = "()" + sig[len("(self)"):]
            elif kind == "classmethod" and sig.startswith("(cls, "):
                sig = "(" + sig[len("(cls, "):]
            doc = inspect.getdoc(member)
            first = doc.split("\n\n")[0].replace("\n", " ") if doc else ""
            tag = {"property": "property ", "classmethod": "classmethod "}.get(kind, "")
            lines.append(f"- {tag}`{mname}{sig}`" + (f": {first}" if first else ""))
        return lines + [""]
    return [f"### `{name}{_signature(obj)}`", "", _doc(obj), ""]


def render() -> str:
    """The text of docs/api.md."""
    lines = [HEADER]
    module = None
    for name, home in charts._HOMES.items():
        if home != module:
            module = home
            lines += [f"## `charts{home}`", ""]
        lines += _entry(name, getattr(charts, name))
    return "\n".join(lines).rstrip() + "\n"


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--check", action="store_true", help="exit 1 when docs/api.md is stale")
    a = p.parse_args(argv)
    text = render()
    if a.check:
        current = OUT.read_text(encoding="utf-8") if OUT.exists() else ""
        if current != text:
            print(f"{OUT} is stale: run python scripts/api_reference.py", file=sys.stderr)
            return 1
        return 0
    OUT.write_text(text, encoding="utf-8")
    print(f"wrote {OUT} ({len(text.splitlines())} lines)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
