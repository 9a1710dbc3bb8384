"""The ehdfem command: :func:`main`, the entry point, and its commands (:mod:`ehdfem.cli.main`)."""

import sys
from contextlib import contextmanager

INTERRUPTED_AT_START = "stopped by Ctrl-C before the command began; nothing was written"


def main(argv=None) -> int:
    """Run the ehdfem command (:func:`ehdfem.cli.main.main`). Its imports (numpy, scipy, the
    package: about half a second) happen here, so a Ctrl-C during them, or before a command
    handles its own, ends in one line and status 130 as one during a command does."""
    try:
        from .main import main as command

        return command(argv)
    except (KeyboardInterrupt, SystemError) as err:
        if isinstance(err, SystemError) and not caused_by_interrupt(err):
            raise
        words = [word for word in (sys.argv[1:] if argv is None else argv) if word[:1] != "-"]
        name = f"ehdfem {words[0]}" if words else "ehdfem"
        print(f"{name}: interrupted: {INTERRUPTED_AT_START}", file=sys.stderr)
        return 130


def caused_by_interrupt(error: BaseException) -> bool:
    """Whether ``error`` is, or was caused by, a Ctrl-C: numba, loading a compiled loop from its
    cache when the interrupt comes, raises a SystemError caused by the KeyboardInterrupt."""
    while error is not None:
        if isinstance(error, KeyboardInterrupt):
            return True
        error = error.__cause__ or error.__context__
    return False


@contextmanager
def interrupt_says(message):
    """Within the block, a Ctrl-C (a KeyboardInterrupt, or numba's SystemError caused by one)
    becomes ``KeyboardInterrupt(message())``: the command's own line of what was saved and how
    to go on."""
    try:
        yield
    except (KeyboardInterrupt, SystemError) as err:
        if not caused_by_interrupt(err):
            raise
        raise KeyboardInterrupt(message()) from None
