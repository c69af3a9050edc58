"""docs/python.md's tour: every ```python block, in order, in one namespace, in a temporary
folder: the documentation's examples work as written."""
import os
import re

from conftest import REPO


def test_every_example_of_docs_python_md_runs(data_dir, tmp_path, monkeypatch):
    text = (REPO / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(blocks) >= 6
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("FM_DATA_DIR", str(data_dir))
    monkeypatch.setenv("FM_SOURCE_DIR", str(REPO))
    namespace = {}
    for i, block in enumerate(blocks):
        exec(compile(block, f"docs/python.md block {i + 1}", "exec"), namespace)
    for written in ("lateral.png", "femur.ply", "knee.tra", "radius.tra"):
        assert os.path.getsize(tmp_path / written) > 0, written
    assert all(a["verdict"] in ("ok", "doubtful", "lost") for a in namespace["answers"])
