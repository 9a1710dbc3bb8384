"""Quiet runs (ehdfem.console.quiet): the root logger's filter that hides the libraries'
chatter unless --verbose."""

import logging

from ehdfem.console.quiet import set_quiet


def test_quiet_drops_only_records_below_warning():
    """set_quiet(True) drops the root logger's INFO records (the compiler's build log) and
    keeps its warnings; set_quiet(False) lets INFO through again."""
    root, seen = logging.getLogger(), []
    handler = logging.Handler(logging.INFO)
    handler.emit = seen.append
    level = root.level
    root.addHandler(handler)
    root.setLevel(logging.INFO)
    try:
        set_quiet(True)
        root.info("running build_ext")
        root.warning("kept")
        set_quiet(False)
        root.info("shown again")
    finally:
        set_quiet(False)
        root.removeHandler(handler)
        root.setLevel(level)
    assert [record.getMessage() for record in seen] == ["kept", "shown again"]
