"""Progress in simulated time, one convention for every long call: ``progress`` is False
(silent), True (a tqdm bar) or a callable ``progress(t_done, t_total)``."""
from __future__ import annotations

__all__ = ["progress_reporter", "check_progress"]


class _Reporter:
    """Reports the simulated time done to a tqdm bar and/or a callback."""

    def __init__(self, progress, total, desc):
        self.total = float(total)
        self.done = 0.0
        self.callback = progress if callable(progress) else None
        self.bar = None
        if progress is True:
            from tqdm.auto import tqdm
            self.bar = tqdm(total=round(self.total, 10), desc=desc, unit="t", leave=False)

    def update(self, t):
        self.done += t
        if self.bar is not None:
            self.bar.update(t)
        if self.callback is not None:
            self.callback(self.done, self.total)

    def close(self):
        if self.bar is not None:
            self.bar.close()


def check_progress(progress):
    """``progress`` itself; ValueError unless False/None, True or callable."""
    if not (progress is True or progress is False or progress is None or callable(progress)):
        raise ValueError(f"progress must be True, False or callable(t_done, t_total), got {progress!r}")
    return progress


def progress_reporter(progress, total, desc) -> _Reporter:
    """Progress in simulated time: ``progress`` False (silent), True (a tqdm bar) or a
    callable ``progress(t_done, t_total)``."""
    return _Reporter(check_progress(progress), total, desc)
