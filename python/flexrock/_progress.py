# SPDX-License-Identifier: BSD-3-Clause
"""Progress of a study in Python: a bar (tqdm where it is installed, a plain line on stderr
otherwise) and a callback, both fed by the study's runs from the main thread while the runs go
on worker threads without the GIL (python/src/bind_study.cpp calls ``reporter``)."""

import sys
import time

# the bar appears only for studies that last longer than this [s], as the command line's
_BAR_DELAY = 1.0


class _Line:
    """A plain progress line on stderr, redrawn in place (a terminal) or written as lines (a log,
    a notebook's stream) every tenth of the runs."""

    def __init__(self, what, total):
        self.what, self.total = what, total
        self.start = time.monotonic()
        self.drawn = False
        self.tenth = 0
        self.tty = sys.stderr.isatty()

    def update(self, done):
        elapsed = time.monotonic() - self.start
        if elapsed < _BAR_DELAY or self.total <= 0:
            return
        rate = done / elapsed
        left = (self.total - done) / rate if rate > 0 else float("nan")
        text = (f"{self.what}: {done} of {self.total} runs ({100.0 * done / self.total:.0f}%), "
                f"{rate:.3g} runs/s, {left:.0f} s left")
        if self.tty:
            sys.stderr.write("\r" + text + "\033[K")
        else:
            tenth = int(10 * done / self.total)
            if tenth <= self.tenth and self.drawn:
                return
            self.tenth = tenth
            sys.stderr.write(text + "\n")
        sys.stderr.flush()
        self.drawn = True

    def close(self):
        if self.drawn and self.tty:
            sys.stderr.write("\n")
            sys.stderr.flush()


class _Tqdm:
    def __init__(self, tqdm, what, total):
        self.bar = tqdm(total=total, desc=what, unit="run", delay=_BAR_DELAY, leave=False)
        self.done = 0

    def update(self, done):
        self.bar.update(done - self.done)
        self.done = done

    def close(self):
        self.bar.close()


class _Reporter:
    def __init__(self, bar, callback):
        self.bar, self.callback = bar, callback

    def __call__(self, done, total):
        if self.bar is not None:
            self.bar.update(done)
        if self.callback is not None:
            self.callback(done, total)

    def close(self):
        if self.bar is not None:
            self.bar.close()


def _bar(what, total):
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return _Line(what, total)
    return _Tqdm(tqdm, what, total)


def reporter(progress, callback, what, total):
    """What a study calls with (runs done, runs to do) while it runs, and closes at the end:
    None when neither a bar (``progress``) nor ``callback`` is asked for."""
    if not isinstance(progress, bool):
        raise TypeError(f"progress: expected True or False, got {progress!r} "
                        "(a function of (done, total) goes to callback=)")
    if callback is not None and not callable(callback):
        raise TypeError(f"callback: expected a function of (done, total) or None, got {callback!r}")
    if not progress and callback is None:
        return None
    return _Reporter(_bar(what, total) if progress else None, callback)
