"""The sections of a markdown report that several studies write into (docs/validation.md): each
study replaces its own section and leaves every other one where it stands.

A section is a line "## heading" and the lines after it up to the next "## " line or the end.
"""

from __future__ import annotations

from pathlib import Path

from .sweep import write_atomic


def _sections(text: str) -> list[tuple[str | None, list[str]]]:
    """(heading, lines) of each section in order, the text before the first one under None."""
    sections: list[tuple[str | None, list[str]]] = [(None, [])]
    for line in text.splitlines():
        if line.startswith("## "):
            sections.append((line, []))
        sections[-1][1].append(line)
    return sections


def replace_section(path: Path, heading: str, lines: list[str], after: str | None = None):
    """Write the section ``heading`` (a "## " line) with the body ``lines`` into the report at
    ``path``: in place of an earlier one, else after the section ``after`` (a heading), else at
    the end. Every other section is kept as it is; the file is replaced atomically."""
    if not heading.startswith("## "):
        raise ValueError(f"a section's heading starts with '## ', not {heading!r}")
    sections = _sections(path.read_text()) if path.exists() else [(None, [])]
    names = [name for name, _ in sections]
    if heading in names:
        sections[names.index(heading)] = (heading, [heading, "", *lines])
    else:
        where = names.index(after) + 1 if after is not None and after in names else len(sections)
        sections.insert(where, (heading, [heading, "", *lines]))
    blocks = ["\n".join(body).strip("\n") for _, body in sections]
    write_atomic(path, "\n\n".join(block for block in blocks if block) + "\n")
