"""The generated modules shipped in ``generated/`` (``charts.generated``), imported:
`import_shipped` imports one module and, when the installed file is damaged (truncated,
edited, not Python), says which file and the command that repairs it instead of a traceback
from inside it.  They are written and compared by ``charts.codegen.regenerate``.
"""
from __future__ import annotations

import importlib
import importlib.util
import sys

__all__ = ["import_shipped", "DamagedModuleError", "REPAIR"]

#: What repairs a damaged or stale shipped module (rewrites charts.generated in place).
REPAIR = "`charts generate` (or reinstall charts)"


class DamagedModuleError(ImportError):
    """A shipped generated module that does not import; the message names the file and
    `REPAIR`."""


def _origin(full: str) -> str:
    """The file a module would be imported from (found without executing it)."""
    try:
        spec = importlib.util.find_spec(full)
    except Exception:               # noqa: BLE001 - the message must not fail in turn
        spec = None
    return spec.origin if spec is not None and spec.origin else full


def import_shipped(name: str):
    """``charts.generated.<name>``; `DamagedModuleError` naming the file and `REPAIR` when it
    exists but does not import, or imports without its last line (``COMPLETE``: cut short)."""
    full = f"charts.generated.{name}"
    try:
        mod = importlib.import_module(full)
        if getattr(mod, "COMPLETE", False) is not True:
            sys.modules.pop(full, None)
            raise ImportError("the file ends before its last line (COMPLETE = True): cut short")
        return mod
    except ModuleNotFoundError as exc:
        if exc.name in (full, "charts.generated"):
            raise DamagedModuleError(f"{full} is missing from this installation; repair it "
                                     f"with {REPAIR}") from None
        raise
    except Exception as exc:        # noqa: BLE001 - whatever a damaged file raises
        raise DamagedModuleError(
            f"{_origin(full)}: the shipped generated module is damaged and does not "
            f"import ({type(exc).__name__}: {' '.join(str(exc).split())[:200]}); repair it "
            f"with {REPAIR}") from None
