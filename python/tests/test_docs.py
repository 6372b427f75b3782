"""The example of docs/python.md runs as written."""

import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_the_python_page_example_runs(capsys):
    text = (ROOT / "docs" / "python.md").read_text(encoding="utf-8")
    block = re.search(r"```python\n(.*?)```", text, re.S).group(1)
    exec(compile(block, "docs/python.md", "exec"), {})
    printed = capsys.readouterr().out.split()
    # The figures the page quotes in its comments.
    assert printed[0].startswith("64.9"), printed
    assert printed[1:4] == ["(46,", "181,", "3)"], printed
