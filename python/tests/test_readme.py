"""README.md shows both library usage examples verbatim: each example file's
full text is the body of one fenced code block."""

import re

import pytest

from conftest import SOURCE_DIR

EXAMPLES = ["examples/python/quickstart.py", "examples/cpp/mesh_cube.cpp"]


def fenced_blocks(markdown):
    """The bodies of the ``` fenced code blocks, each ending with its last newline."""
    return re.findall(r"^```[^\n]*\n(.*?)^```[ \t]*$", markdown, flags=re.MULTILINE | re.DOTALL)


@pytest.mark.parametrize("example", EXAMPLES)
def test_readme_shows_the_example(example):
    text = (SOURCE_DIR / example).read_text()
    blocks = fenced_blocks((SOURCE_DIR / "README.md").read_text())
    assert text in blocks, f"README.md has no fenced code block with the text of {example}"
