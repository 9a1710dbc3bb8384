"""The installed version of ehdfem (recorded in study tables and results)."""

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("ehdfem")
except PackageNotFoundError:  # running from a source tree that was not installed
    __version__ = "0+unknown"
