"""Speed of the Python module against the command line (docs/python.md).

    scripts/python python/benchmark.py [ROWS]

Rigid designs in the paper's parametrisation (Table I's row 1 with the length,
mass, head/handle mass ratio and impact point varied), evaluated on one thread
by `sweetspot evaluate --batch` from a CSV file and by sweetspot.evaluate_many
from NumPy arrays; then `import sweetspot` in a fresh interpreter and one
evaluate(dict). Prints rows per second and the ratio."""

import csv
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np
import sweetspot

ROOT = pathlib.Path(__file__).resolve().parents[1]
CLI = os.environ.get("SWEETSPOT_CLI", str(ROOT / "build" / "sweetspot"))
BASE = ROOT / "designs" / "table1" / "row1.json"


def best_of(runs, work):
    best = float("inf")
    for _ in range(runs):
        start = time.perf_counter()
        work()
        best = min(best, time.perf_counter() - start)
    return best


def main():
    rows = int(sys.argv[1]) if len(sys.argv) > 1 else 200_000
    rng = np.random.default_rng(2004)
    columns = {
        "implement.length_m": rng.uniform(0.6, 0.75, rows),
        "implement.mass_kg": rng.uniform(0.2, 0.4, rows),
        "implement.head_to_handle_mass_ratio": rng.uniform(0.6, 1.2, rows),
        "impact.from_tip_m": rng.uniform(0.0, 0.3, rows),
    }
    with tempfile.TemporaryDirectory() as folder:
        table = pathlib.Path(folder) / "rows.csv"
        with open(table, "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(columns)
            writer.writerows(zip(*(map(repr, v.tolist()) for v in columns.values())))
        command = [CLI, "evaluate", "--batch", str(table), "--base", str(BASE), "--threads", "1",
                   "-q", "-o", str(pathlib.Path(folder) / "out.csv")]
        cli = best_of(3, lambda: subprocess.run(command, check=True))
    many = best_of(3, lambda: sweetspot.evaluate_many(BASE, columns, threads=1))
    result = sweetspot.evaluate_many(BASE, columns, threads=1)
    assert result["ok"].all()
    print(f"{rows} rigid rows on one thread:")
    print(f"  sweetspot evaluate --batch (CSV in and out)  {cli:7.3f} s  {rows / cli:10.0f} rows/s")
    print(f"  sweetspot.evaluate_many (NumPy in and out)   {many:7.3f} s  {rows / many:10.0f} rows/s"
          f"  ({cli / many:.1f}x)")
    threads = os.cpu_count() or 1
    wide = best_of(3, lambda: sweetspot.evaluate_many(BASE, columns, threads=threads))
    print(f"  sweetspot.evaluate_many, {threads} threads          {wide:7.3f} s  {rows / wide:10.0f} rows/s")

    code = "import time; t = time.perf_counter(); import sweetspot; print(time.perf_counter() - t)"
    imports = [float(subprocess.run([sys.executable, "-c", code], check=True, capture_output=True,
                                    text=True).stdout) for _ in range(5)]
    print(f"import sweetspot: {1e3 * min(imports):.1f} ms (best of 5 fresh interpreters)")
    design = json.loads(BASE.read_text())
    calls = 2000
    one = best_of(3, lambda: [sweetspot.evaluate(design) for _ in range(calls)]) / calls
    print(f"evaluate(dict) of one rigid design: {1e6 * one:.1f} us")


if __name__ == "__main__":
    main()
