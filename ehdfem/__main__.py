"""`python -m ehdfem`: the ehdfem command (:func:`ehdfem.cli.main`)."""

from .cli import main

if __name__ == "__main__":
    raise SystemExit(main())
