"""The Python package against the command line (issue 14): every scene of scenes/ gives the
result `snooker simulate --json` gives, bit for bit; many at once on any thread count give the
same; positions from the exact trajectory; plans; bad input raises with the CLI's messages."""

import json
import math
import os
import pathlib
import subprocess

import numpy as np
import pytest

import snooker

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENES = sorted((ROOT / "scenes").glob("*.toml"))
CLI = pathlib.Path(os.environ.get("SNOOKER_CLI", ROOT / "target" / "release" / "snooker"))
TWO_BALLS = {
    "name": "two-balls",
    "balls": [{"id": "cue", "pos": [1.0, 0.8]}, {"id": "red", "pos": [2.0, 0.9]}],
    "cue": {"ball": "cue", "speed": 2.0, "aim": 0.1},
}
NEVER_STOPS = "params = {sidespin_decel = 0.0}\nballs = [{id = 'cue', pos = [1.0, 0.9], spin = [0.0, 0.0, 20.0]}]\n"


def cli(*args):
    return subprocess.run([str(CLI), *args], capture_output=True, text=True)


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_every_scene_equals_the_cli_to_the_bit(path):
    if not CLI.exists():
        pytest.fail(f"the command line is not built: {CLI} (cargo build --release)")
    out = cli("simulate", str(path), "--quiet", "--json", "-")
    assert out.returncode == 0, out.stderr
    want = json.loads(out.stdout)
    # JSON floats are written shortest-exact and read exactly: equal dicts are equal bits.
    assert snooker.simulate(path).result.to_dict() == want
    assert snooker.simulate(str(path)).result.to_dict() == want
    got = snooker.simulate(path.read_text()).result
    assert [e.to_dict() for e in got.events] == want["events"]


def test_the_cloth_s_friction_during_a_steep_strike_reads_as_the_cli_writes_it(tmp_path):
    # mu_strike_cloth (physics.md, "Cue strike"): the strike's cloth_friction is written only
    # when the cloth's friction acted, and reads back key for key.
    scene = tmp_path / "masse.toml"
    scene.write_text(
        "name = 'masse'\n[params]\nmu_strike_cloth = 0.21\n"
        "[[balls]]\nid = 'cue'\npos = [1.0, 0.9]\n"
        "[cue]\nball = 'cue'\nspeed = 3.0\naim = 0.0\noffset = [0.008, 0.0]\nelevation = 1.2\n"
    )
    out = cli("simulate", str(scene), "--quiet", "--json", "-")
    assert out.returncode == 0, out.stderr
    want = json.loads(out.stdout)
    got = snooker.simulate(scene).result
    assert got.to_dict() == want
    friction = got.strike.cloth_friction
    assert friction is not None and math.hypot(*friction) > 0.0
    assert got.params["mu_strike_cloth"] == 0.21
    # The level cue: no friction, no key.
    level = snooker.simulate(TWO_BALLS).result
    assert level.strike.cloth_friction is None and "cloth_friction" not in level.to_dict()["strike"]


def test_many_at_once_equal_one_by_one_on_any_thread_count():
    scenes = [str(p) for p in SCENES] + [TWO_BALLS]
    one_by_one = [snooker.simulate(s).result for s in scenes]
    for threads in (None, 1, 2, 3):
        got = [s.result for s in snooker.simulate_many(scenes, threads=threads)]
        assert got == one_by_one, threads


def test_numpy_values_in_a_dict_scene_are_the_numbers_they_hold():
    as_numpy = {
        "name": "two-balls",
        "balls": [
            {"id": "cue", "pos": np.array([1.0, 0.8])},
            {"id": "red", "pos": np.array([2.0, 0.9])},
        ],
        "cue": {"ball": "cue", "speed": np.float64(2.0), "aim": np.float64(0.1)},
        "sim": {"max_events": np.int64(100000)},
    }
    want = snooker.simulate({**TWO_BALLS, "sim": {"max_events": 100000}}).result
    assert snooker.simulate(as_numpy).result == want


def test_positions_follow_the_exact_trajectory():
    shot = snooker.simulate(TWO_BALLS)
    times = np.linspace(0.0, shot.duration, 50)
    pos = shot.positions(times)
    assert pos.shape == (50, 2, 3) and pos.dtype == np.float64
    assert pos[0, 0].tolist() == [1.0, 0.8, shot.result.params["ball_radius"]]
    for i, ball in enumerate(shot.ball_ids):
        assert tuple(pos[-1, i].tolist()) == shot.final[ball].pos
    # The red is struck: it moves between its events and stops.
    assert not np.array_equal(pos[10, 1], pos[0, 1])
    with pytest.raises(ValueError, match="outside the shot"):
        shot.positions([shot.duration + 1.0])


def test_bad_scenes_raise_value_errors_with_the_cli_messages(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[[balls]]\nid = 'a'\npos = [0.5, 0.5, 0.3]\n")
    out = cli("simulate", str(bad))
    assert out.returncode == 2
    with pytest.raises(ValueError) as e:
        snooker.simulate(bad)
    assert str(e.value) == out.stderr.strip().removeprefix("error: ")
    for scene, says in [
        ({"balls": [{"id": "a", "pos": [0.5, 0.5]}], "unknown": 1}, "unknown"),
        (
            {"balls": [{"id": "a", "pos": [0.5, math.nan]}]},
            r"key `balls\[0\]\.pos`: must be a finite number, got NaN",
        ),
        (
            {"params": {"mu_slide": np.float64(np.inf)}, "balls": [{"id": "a", "pos": [0.5, 0.5]}]},
            r"key `params\.mu_slide`: must be a finite number, got inf",
        ),
        (
            {"balls": [{"id": "a", "pos": [0.5, 0.5], "vel": {1, 2, 3}}]},
            r"key `balls\[0\]\.vel`: unexpected type: 'set' object is not an instance of",
        ),
        ({"balls": []}, "no balls"),
        (str(tmp_path / "missing.toml"), "cannot read"),
        (42, "not int"),
    ]:
        with pytest.raises(ValueError, match=says):
            snooker.simulate(scene)
    with pytest.raises(ValueError, match=r"scenes\[1\]"):
        snooker.simulate_many([TWO_BALLS, {"balls": []}])
    with pytest.raises(ValueError, match="threads"):
        snooker.simulate_many([TWO_BALLS], threads=0)


def test_a_shot_that_cannot_end_is_a_simulation_error():
    with pytest.raises(snooker.SimulationError, match="still moving"):
        snooker.simulate(NEVER_STOPS)
    got = snooker.simulate_many([TWO_BALLS, NEVER_STOPS], errors="return")
    assert isinstance(got[0], snooker.Shot)
    assert isinstance(got[1], snooker.SimulationError)
    with pytest.raises(snooker.SimulationError):
        snooker.simulate_many([TWO_BALLS, NEVER_STOPS])


def test_the_chapter_7_plan_equals_the_cli():
    ch7 = ROOT / "scenes" / "chapter7-example.toml"
    args = ("red", "middle-left", (1.25, 0.0262))
    plan = snooker.plan(ch7, *args, samples=32, noise={"aim": 0.002}, bounds={"speed": (0.3, 6)})
    assert plan.reached and plan.best.potted and plan.best.distance < 0.001
    out = cli("plan", str(ch7), "--pot", "red", "--pocket", "middle-left", "--cue-to",
              "1.25,0.0262", "--samples", "32", "--noise", "aim=0.002", "--bounds",
              "speed=0.3..6", "--json", "-", "--quiet")
    assert out.returncode == 0, out.stderr
    want = json.loads(out.stdout)
    assert plan.best.strike.to_dict() == want["best"]["strike"]
    with pytest.raises(ValueError, match="pocket"):
        snooker.plan(ch7, "red", "no-such-pocket", (1.25, 0.0262))
    with pytest.raises(ValueError, match=r"^noise\['aim'\]: expected a finite number") as e:
        snooker.plan(ch7, "red", "middle-left", (1.25, 0.0262), noise={"aim": -1.0})
    assert "--" not in str(e.value)
    with pytest.raises(ValueError, match=r"^bounds\['speed'\]: outside the engine's strike"):
        snooker.plan(ch7, "red", "middle-left", (1.25, 0.0262), bounds={"speed": (0.3, 40)})
    with pytest.raises(ValueError, match=r"^cue_to: "):
        snooker.plan(ch7, "red", "middle-left", (9.0, 0.5))


def test_the_batch_table_reads_in_pyarrow(tmp_path):
    pq = pytest.importorskip("pyarrow.parquet")
    out = tmp_path / "r.parquet"
    run = cli("batch", str(ROOT / "scenes"), "--out", str(out), "--quiet")
    assert run.returncode == 0, run.stderr
    table = pq.read_table(out).to_pylist()
    assert len(table) == len(SCENES)
    for row, path in zip(table, SCENES):
        shot = snooker.simulate(path)
        assert row["source"].endswith(path.name) and row["error"] is None
        assert row["duration"] == shot.duration
        assert row["events"] == len(shot.events)
        assert row["ball"] == shot.ball_ids
        assert row["x"] == [shot.final[b].pos[0] for b in shot.ball_ids]
        assert row["pot_ball"] == [p.ball for p in shot.pots]


@pytest.mark.parametrize(
    "call, args",
    [
        (lambda: snooker.impact_ball_ball(2.0, cut=30, topspin=1.0, params={"mu_ball": 0.06}),
         ["ball-ball", "--speed", "2", "--cut", "30", "--topspin", "1", "--param", "mu_ball=0.06"]),
        (lambda: snooker.impact_cushion(1.5, angle=45, sidespin=-0.5),
         ["cushion", "--speed", "1.5", "--angle", "45", "--sidespin", "-0.5"]),
    ],
)
def test_impacts_equal_the_cli(call, args):
    out = cli("impact", *args, "--json")
    assert out.returncode == 0, out.stderr
    assert call().to_dict() == json.loads(out.stdout)


def test_bad_impacts_raise_the_cli_messages():
    out = cli("impact", "ball-ball", "--speed", "30", "--json")
    assert out.returncode == 2
    with pytest.raises(ValueError) as e:
        snooker.impact_ball_ball(30.0)
    # The same message, naming the Python argument where the command names its flag.
    assert "--" + str(e.value) == out.stderr.strip().removeprefix("error: ")
    assert str(e.value).startswith("speed must lie in")
    with pytest.raises(ValueError, match="mu_bal"):
        snooker.impact_cushion(1.0, params={"mu_bal": 0.1})
