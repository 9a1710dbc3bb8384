"""The ehdfem command (main)."""
