"""docs/python.md stays true: every ```python snippet runs, in order, in one namespace, from the
source tree as a reader would (paths like data/demo/...); the snippets write only to a
temporary folder (plots with the Agg backend)."""
import re

from conftest import SOURCE_DIR


def snippets():
    text = (SOURCE_DIR / "docs" / "python.md").read_text(encoding="utf-8")
    return re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)


def test_every_snippet_of_the_python_doc_runs(monkeypatch):
    import matplotlib
    matplotlib.use("Agg")
    monkeypatch.chdir(SOURCE_DIR)
    code = snippets()
    assert code, "docs/python.md has no python snippet"
    namespace = {}
    for i, snippet in enumerate(code):
        exec(compile(snippet, f"docs/python.md snippet {i + 1}", "exec"), namespace)
