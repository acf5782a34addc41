"""The path T example: the same steps as `proxima path`, and its plot."""

import csv
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

from conftest import BUNNY
from test_cli import cli  # noqa: F401 (the fixture)

EXAMPLES = pathlib.Path(__file__).resolve().parents[1] / "examples"
sys.path.insert(0, str(EXAMPLES))
import path_t  # noqa: E402


def test_path_t_equals_the_cli(cli, tmp_path):  # noqa: F811
    steps = 40
    out = tmp_path / "path.csv"
    subprocess.run([cli, "path", "--steps", str(steps), "--csv", str(out)], check=True, capture_output=True,
                   env={**os.environ, "PROXIMA_ASSETS": str(BUNNY.parent)})
    with open(out) as f:
        expected = list(csv.DictReader(f))
    results = path_t.run_path(BUNNY, steps)
    rows = [(m, r) for m in ("precise", "original") for r in results[m]]
    assert len(rows) == len(expected) == 2 * steps
    assert sum(r["lmds"] > 0 for _, r in rows) > 0
    for (method, row), e in zip(rows, expected):
        assert e["method"] == method
        assert "%.9g" % row["x"] == e["x"]
        assert "%.9g" % row["min_distance"] == e["min_distance"]
        assert (row["candidates"], row["lmds"]) == (int(e["candidates"]), int(e["lmds"]))
        assert ["%.9g" % v for v in row["force"]] == [e["force_x"], e["force_y"], e["force_z"]]


def test_path_t_writes_its_plot(tmp_path):
    png = tmp_path / "path_t.png"
    assert path_t.main([str(BUNNY), "--steps", "30", "--out", str(png)]) == 0
    data = png.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 10000
    width, height = np.frombuffer(data[16:24], dtype=">u4")
    assert (width, height) == (800, 1000)


def test_haptic_trace_plots_the_clis_trace(cli, tmp_path):  # noqa: F811
    import haptic_trace
    out = tmp_path / "trace.csv"
    subprocess.run([cli, "run", "--seconds", "0.5", "--hold", "0.2", "--trace", str(out)], check=True,
                   capture_output=True, env={**os.environ, "PROXIMA_ASSETS": str(BUNNY.parent)})
    trace = haptic_trace.read_csv(out)
    assert len(trace) > 500 and np.all(np.diff(trace["tick"].astype(np.int64)) == 1)
    magnitude, step, frequency, spectrum = haptic_trace.figures(trace)
    assert magnitude.max() > 0 and magnitude[-1] == 0, "the run touched, then faded out at the stop"
    assert len(frequency) == len(spectrum) and frequency[-1] == pytest.approx(500, rel=0.2)
    png = tmp_path / "trace.png"
    assert haptic_trace.main(["--csv", str(out), "--out", str(png)]) == 0
    assert png.stat().st_size > 10000


def test_haptic_trace_records_its_own_run(tmp_path):
    import haptic_trace
    trace = haptic_trace.record(BUNNY, seconds=0.3, hold=0.1)
    assert len(trace) > 400
    assert np.linalg.norm(trace["force"], axis=1).max() > 0
