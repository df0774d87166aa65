"""Re-execute notebooks in place with nbclient (after a change to src/handbook).

Usage: python tools/run_notebooks.py [NOTEBOOK ...]   (default: every chapter of the book)
Stops at the first cell that raises, naming the notebook and cell.
"""
import sys
from pathlib import Path

import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError

root = Path(__file__).resolve().parents[1]
paths = [Path(p) for p in sys.argv[1:]] or sorted((root / "book").rglob("*.ipynb"))
for path in paths:
    if "_build" in path.parts or ".ipynb_checkpoints" in path.parts:
        continue
    nb = nbformat.read(path, as_version=4)
    try:
        NotebookClient(nb, timeout=300, kernel_name="python3", record_timing=False,
                       resources={"metadata": {"path": str(path.parent)}}).execute()
    except CellExecutionError as exc:
        sys.exit(f"{path}: {exc}")
    nbformat.write(nb, path)
    print("executed", path.relative_to(root) if path.is_absolute() else path)
