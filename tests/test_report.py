"""A study's section of a shared report is replaced in place and leaves the others alone."""

import pytest

from ehdfem.study.report import replace_section

pytestmark = pytest.mark.serial

REPORT = "# Title\n\nIntro.\n\n## A\n\na text\n\n## B\n\nb text\n"


def test_a_section_is_replaced_in_place(tmp_path):
    path = tmp_path / "r.md"
    path.write_text(REPORT)
    replace_section(path, "## A", ["new a"])
    assert path.read_text() == "# Title\n\nIntro.\n\n## A\n\nnew a\n\n## B\n\nb text\n"


def test_a_new_section_goes_after_the_one_named_or_at_the_end(tmp_path):
    path = tmp_path / "r.md"
    path.write_text(REPORT)
    replace_section(path, "## C", ["c text"], after="## A")
    assert path.read_text().index("## C") < path.read_text().index("## B")
    replace_section(path, "## D", ["d text", ""])
    assert path.read_text().endswith("## B\n\nb text\n\n## D\n\nd text\n")
    replace_section(path, "## C", ["c again"])  # in place, the rest unchanged
    text = path.read_text()
    assert text.count("## C") == 1 and "c again" in text and "c text" not in text
    assert text.startswith("# Title\n\nIntro.\n\n## A\n\na text\n\n## C\n\nc again\n\n## B")


def test_a_heading_must_be_a_section(tmp_path):
    with pytest.raises(ValueError, match="## "):
        replace_section(tmp_path / "r.md", "# A", [])
