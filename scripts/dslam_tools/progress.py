"""A plain-text progress bar on stderr: `[#####     ] 150/602`."""

import sys
import time


class ProgressBar(object):
    """Redraws one line with '\\r' on a terminal (at most every 0.1 s); when stderr is not a
    terminal (logs, tests) prints a full line at every 10 % instead."""

    def __init__(self, total, width=30, stream=None):
        self._total = max(int(total), 1)
        self._width = width
        self._stream = stream or sys.stderr
        self._tty = hasattr(self._stream, "isatty") and self._stream.isatty()
        self._last_draw = 0.0
        self._last_decile = -1

    def update(self, done):
        """Shows `done` of the total items processed."""
        now = time.time()
        if self._tty:
            if done < self._total and now - self._last_draw < 0.1:
                return
            self._stream.write("\r" + self.render(done))
            if done >= self._total:
                self._stream.write("\n")
        else:
            decile = done * 10 // self._total
            if decile == self._last_decile:
                return
            self._last_decile = decile
            self._stream.write(self.render(done) + "\n")
        self._last_draw = now
        self._stream.flush()

    def render(self, done):
        """The bar text for `done` items, e.g. '[#####     ] 150/300'."""
        filled = int(round(self._width * min(done, self._total) / float(self._total)))
        return "[%s%s] %d/%d" % ("#" * filled, " " * (self._width - filled), done, self._total)
