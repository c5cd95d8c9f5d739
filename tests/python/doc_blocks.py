"""The one fenced block of a page of docs/ with a given tag (```python TAG), as the docs' tests run it."""
import pathlib
import re

SOURCE = pathlib.Path(__file__).resolve().parents[2]


def one_block(page, tag):
    """The code of the single ```python TAG block of docs/PAGE (an assertion error if there is not exactly one)."""
    text = (SOURCE / "docs" / page).read_text()
    blocks = re.findall(rf"```python {tag}\n(.*?)```", text, re.S)
    assert len(blocks) == 1, f"docs/{page} must hold one ```python {tag} block"
    return blocks[0]
