"""The notebook in examples/ runs as an engineer runs it (nbclient, Debian's
python3 kernel): every cell without an error, the plot drawn."""

import os

import nbclient
import nbformat
import sweetspot
from conftest import ROOT

NOTEBOOK = ROOT / "examples" / "notebook" / "catalogue.ipynb"


def test_the_notebook_runs_and_plots():
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    # Committed without outputs: what it shows comes from this run.
    assert all(not cell.get("outputs") for cell in notebook.cells if cell.cell_type == "code")
    os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")
    # The kernel (its own process, in the notebook's folder) imports the module under test.
    here = os.path.dirname(os.path.abspath(sweetspot.__file__))
    os.environ["PYTHONPATH"] = os.pathsep.join([here, os.environ.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    client = nbclient.NotebookClient(notebook, timeout=120, kernel_name="python3",
                                     resources={"metadata": {"path": str(NOTEBOOK.parent)}})
    client.execute()  # raises CellExecutionError naming the cell that failed
    outputs = [o for cell in notebook.cells if cell.cell_type == "code" for o in cell.outputs]
    assert any("image/png" in o.get("data", {}) for o in outputs)
    text = "".join(o.get("text", "") for o in outputs if o.get("output_type") == "stream")
    assert "Coach's 100" in text and "expected a finite number, got nan" in text
    assert "optimum" in text
