"""The Python blocks of the README and the book run as written, from the repository's root
(a name used before it is defined, an argument renamed: the README's tour once called
simulate_many on an undefined `scene_dict`)."""

import os
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
PAGES = ["README.md", "docs/python.md", "docs/rules.md", "docs/playing.md"]


def blocks():
    for page in PAGES:
        text = (ROOT / page).read_text()
        for m in re.finditer(r"```python\n(.*?)```", text, re.S):
            line = text[: m.start()].count("\n") + 1
            yield pytest.param(m.group(1), id=f"{page}:{line}")


def test_every_page_named_has_a_python_block():
    assert {p.id.split(":")[0] for p in blocks()} == set(PAGES)


@pytest.mark.parametrize("code", list(blocks()))
def test_the_block_runs_as_written(code, monkeypatch):
    # The player's block plays a whole visit at effort 4000 (seconds of search per stroke);
    # the same code at effort 200 exercises every call it makes.
    code = code.replace("effort=4000", "effort=200")
    monkeypatch.chdir(ROOT)
    exec(compile(code, "<doc block>", "exec"), {"__name__": "doc_block"})
    assert os.getcwd() == str(ROOT)
