"""`python -m ehdfem`: the ehdfem command (:mod:`ehdfem.cli.main`)."""

from .cli.main import main

if __name__ == "__main__":
    raise SystemExit(main())
