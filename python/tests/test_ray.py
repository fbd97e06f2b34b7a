"""The Ray sweep (examples/ray_sweep.py) on a local Ray instance of 2 CPUs gives exactly what
`simulate_many` gives on the same scenes."""

import pathlib
import sys

import pytest

ray = pytest.importorskip("ray")
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "examples"))
import ray_sweep  # noqa: E402

import snooker  # noqa: E402


def test_a_sweep_through_ray_equals_simulate_many(tmp_path):
    positions = ray_sweep.grid(4, 3)
    scenes = ray_sweep.scenes(positions, samples=8, seed=3)
    try:
        ray_sweep.connect(num_cpus=2)
        through_ray = ray_sweep.sweep(positions, samples=8, seed=3, per_task=2)
    finally:
        ray.shutdown()
    local = ray_sweep.rows(snooker.simulate_many(scenes, errors="return"))
    assert len(through_ray) == len(scenes) == 96
    assert through_ray == local
    assert any(r["potted"] for r in local) and not all(r["potted"] for r in local)
    pq = pytest.importorskip("pyarrow.parquet")
    out = tmp_path / "sweep.parquet"
    pq.write_table(ray_sweep.table(positions, 8, through_ray), out)
    assert pq.read_table(out).num_rows == 96
