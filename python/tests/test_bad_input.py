"""Bad input through the Python API (the project's standard: one clear error naming the
argument or key and the reason; never a panic, never a silent guess, never a file that does
not read back)."""

import json
import math
import pathlib
import re

import pytest

import snooker

STRIKE = {"speed": 2.0, "aim": 0.0465}


@pytest.mark.parametrize("key", ["spin", "sped", "offset_side"])
def test_a_strike_with_an_unknown_key_is_refused_naming_it(key):
    # Before: the key was ignored and the stroke played without it (a typo'd "elevation"
    # played level).
    frame = snooker.Frame.break_off()
    with pytest.raises(ValueError, match=f"strike: unknown key `{key}`"):
        frame.play({**STRIKE, key: 0.1})
    with pytest.raises(ValueError, match=f"strike: unknown key `{key}`"):
        frame.to_toml({**STRIKE, key: 0.1})


def test_a_strike_on_a_ball_other_than_the_cue_ball_is_refused():
    # Before: `ball` was ignored and the cue ball struck.
    frame = snooker.Frame.break_off()
    with pytest.raises(ValueError, match="strike: `ball` is 'red1', not the cue ball"):
        frame.play({**STRIKE, "ball": "red1"})
    # The cue ball itself, as a decision's strike.to_dict() names it, is welcome.
    verdict, _ = frame.play({**STRIKE, "ball": "cue"})
    assert verdict.shot.result.strike.ball == "cue"


@pytest.mark.parametrize("strike", [None, [2.0, 0.0], "speed", 2.0])
def test_a_strike_that_is_not_a_dict_is_refused_naming_it(strike):
    # Before: "list indices must be integers or slices, not str" and the like.
    with pytest.raises(TypeError, match="^strike: a dict"):
        snooker.Frame.break_off().play(strike)


@pytest.mark.parametrize("value", [True, "2.0", None])
def test_a_strike_value_that_is_not_a_number_is_refused(value):
    # Before: True played as 1 m/s.
    with pytest.raises(ValueError, match="strike: `speed` must be a number"):
        snooker.Frame.break_off().play({**STRIKE, "speed": value})


@pytest.mark.parametrize("bad, key", [
    ({"speed": math.nan}, "cue.speed"),
    ({"speed": 1e300}, "cue.speed"),
    ({"aim": math.inf}, "cue.aim"),
    ({"offset": [0.1, 0.0]}, "cue.offset"),
    ({"elevation": 2.0}, "cue.elevation"),
])
def test_to_toml_refuses_a_strike_play_refuses(bad, key):
    # Before: the frame file was written with `speed = nan` (or 1e300), which no reader takes
    # back ("key `cue.speed`: must be a finite number").
    frame = snooker.Frame.break_off()
    strike = {**STRIKE, **bad}
    with pytest.raises(ValueError, match=f"key `{key}`"):
        frame.play(strike)
    with pytest.raises(ValueError, match=f"key `{key}`"):
        frame.to_toml(strike)
    # A good strike's file reads back with that strike.
    text = frame.to_toml(STRIKE)
    assert snooker.frame(text).scores == frame.scores
    assert snooker.scene(text).ball_ids == list(frame.balls)


@pytest.mark.parametrize("reds", [16, 100, -1, 2**70])
def test_open_table_refuses_a_count_of_reds_it_cannot_rack(reds):
    # Before: 16 or 100 reds silently gave 15; -1 an OverflowError naming nothing.
    with pytest.raises(ValueError, match=r"^reds: must lie in \[0, 15\]"):
        snooker.Frame.open_table(reds)


@pytest.mark.parametrize("seed", [-1, 2**64])
def test_open_table_refuses_a_seed_out_of_range_naming_it(seed):
    with pytest.raises(ValueError, match="^seed: must lie in"):
        snooker.Frame.open_table(3, seed)


@pytest.mark.parametrize("reds", [3.5, True, "3"])
def test_open_table_refuses_a_count_that_is_not_a_whole_number(reds):
    with pytest.raises(TypeError, match="^reds: a whole number"):
        snooker.Frame.open_table(reds)


def test_open_table_takes_whole_numbers_of_any_kind_and_keeps_its_defaults():
    import numpy as np

    assert snooker.Frame.open_table(np.int64(4), np.uint64(7)).balls == \
        snooker.Frame.open_table(4, 7).balls
    assert len(snooker.Frame.open_table().kinds) == 22
    assert len(snooker.Frame.open_table(0).kinds) == 7


@pytest.mark.parametrize("place", [(math.nan, 0.9), (0.7, math.inf), (-math.inf, math.nan)])
def test_nearest_placement_refuses_a_place_that_is_not_finite(place):
    # Before: any NaN gave the D's centre back as "the nearest place".
    with pytest.raises(ValueError, match="^preferred: must be two finite numbers"):
        snooker.Frame.break_off().nearest_placement(place)


CHAPTER7 = pathlib.Path(__file__).resolve().parents[2] / "scenes" / "chapter7-example.toml"


def plan(**kw):
    return snooker.plan(CHAPTER7, "red", "middle-left", (1.25, 0.0262), **{"samples": 8, **kw})


@pytest.mark.parametrize("arg, value", [
    ("samples", -1), ("alternatives", -1), ("seed", -1), ("seed", 2**64),
])
def test_plan_refuses_a_count_or_seed_out_of_range_naming_it(arg, value):
    # Before: "OverflowError: can't convert negative int to unsigned", naming nothing.
    with pytest.raises(ValueError, match=f"^{arg}: must lie in"):
        plan(**{arg: value})


def test_plan_refuses_alternatives_past_its_bound():
    # Before: usize::MAX overflowed the search's count.
    with pytest.raises(ValueError, match="^alternatives: at most 1000"):
        plan(alternatives=2**64 - 1)


@pytest.mark.parametrize("arg, value", [("samples", 2.5), ("seed", 1.5), ("alternatives", True)])
def test_plan_refuses_a_count_or_seed_that_is_not_a_whole_number(arg, value):
    # Before: 2.5 samples were 2, seed 1.5 was seed 1, without a word.
    with pytest.raises(TypeError, match=f"^{arg}: a whole number"):
        plan(**{arg: value})


@pytest.mark.parametrize("call, arg, value, error", [
    ("play", "seed", -1, ValueError), ("play", "effort", -5, ValueError),
    ("play", "max_strokes", -1, ValueError), ("play", "effort", 1e3, TypeError),
    ("choose", "seed", 2**64, ValueError), ("choose", "stroke", -1, ValueError),
    ("choose", "effort", 0.5, TypeError),
    # A safety's samples asked for more memory than exists (a panic).
    ("play", "effort", 2**64 - 1, ValueError), ("choose", "effort", 2**64 - 1, ValueError),
])
def test_play_and_choose_refuse_bad_counts_and_seeds_naming_them(call, arg, value, error):
    # Before: OverflowError naming nothing; effort=0.5 became 0 ("effort: must be at least 1").
    with pytest.raises(error, match=f"^{arg}: "):
        getattr(snooker, call)(snooker.Frame.open_table(2, 1), **{arg: value})


def test_numpy_integers_are_whole_numbers():
    import numpy as np

    a, b = plan(seed=np.uint64(3), samples=np.int32(8)), plan(seed=3, samples=8)
    assert a.best == b.best and a.alternatives == b.alternatives


SCENE = {"balls": [{"id": "cue", "pos": [1.0, 0.8]}, {"id": "red", "pos": [2.0, 0.9]}],
         "cue": {"ball": "cue", "speed": 2.0, "aim": 0.1}}


def test_simulate_many_takes_numpy_thread_counts():
    # Before: "threads: a positive number of threads, not np.int64(2)".
    import numpy as np

    one = snooker.simulate(SCENE)
    many = snooker.simulate_many([SCENE] * 3, threads=np.int64(2))
    assert [(s.events, s.final) for s in many] == [(one.events, one.final)] * 3


@pytest.mark.parametrize("threads, error", [
    (0, ValueError), (-1, ValueError), (2**70, ValueError), (True, TypeError), (2.0, TypeError),
    (1025, ValueError),
])
def test_simulate_many_refuses_a_bad_thread_count_naming_it(threads, error):
    # Before: 2**70 raised a bare OverflowError, True ran on one thread; 1025 was refused only
    # with 1025 scenes or more, the message giving the range as [1, 2^64 - 1].
    with pytest.raises(error, match="^threads: " + ("must lie in \\[1, 1024\\]"
                                                     if error is ValueError else "")):
        snooker.simulate_many([SCENE], threads=threads)


def test_simulate_many_with_far_more_threads_than_scenes_returns_at_once():
    # Before: threads=100_000 for two scenes started tens of thousands of threads and did not
    # come back within minutes (now above MAX_THREADS it is refused, above); at the most
    # allowed, no more threads than scenes are started. Run apart, so that a hang fails the
    # test rather than hanging it.
    import subprocess
    import sys

    code = ("import snooker; s = " + repr(SCENE) +
            "; print(len(snooker.simulate_many([s, s], threads=snooker.MAX_THREADS)))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "2"


@pytest.mark.parametrize("kw, error, message", [
    ({"cue_to": (1.25, 0.0262, 0.0)}, ValueError, r"cue_to: two numbers, got 3"),
    ({"cue_to": "xy"}, TypeError, r"cue_to: two numbers"),
    ({"cue_to": (1.25, "y")}, TypeError, r"cue_to\[1\]: a number"),
    ({"tolerance": "0.001"}, TypeError, r"tolerance: a number"),
    ({"bounds": [1]}, TypeError, r"bounds: a dict"),
    ({"bounds": {"speed": 1}}, TypeError, r"bounds\['speed'\]: two numbers"),
    ({"bounds": {"speed": (0.3, 6.0, 9.0)}}, ValueError, r"bounds\['speed'\]: two numbers"),
    ({"bounds": {"speed": (0.3, True)}}, TypeError, r"bounds\['speed'\]\[1\]: a number"),
    ({"noise": {"aim": "x"}}, TypeError, r"noise\['aim'\]: a number"),
    ({"noise": {"aim": True}}, TypeError, r"noise\['aim'\]: a number"),
    ({"noise": [1]}, TypeError, r"noise: expected 'standard', 0 or a dict"),
    ({"noise": False}, TypeError, r"noise: expected 'standard', 0 or a dict"),
    ({"noise": "standard*-1"}, ValueError, r"noise: expected standard\*K with K >= 0"),
    ({"noise": "loud"}, ValueError, r"noise: expected 'standard', 'standard\*K', 0 or a dict"),
])
def test_plan_refuses_a_malformed_argument_naming_it(kw, error, message):
    # Before: "too many values to unpack", AttributeError "'list' object has no attribute
    # 'items'", "could not convert string to float: 'x'" (naming no argument); True as a
    # standard deviation of 1 rad and False as no noise at all.
    args = {"cue_to": (1.25, 0.0262), **kw}
    with pytest.raises(error, match="^" + message):
        snooker.plan(CHAPTER7, "red", "middle-left", samples=8, **args)


def test_plan_takes_numpy_pairs_and_numbers():
    import numpy as np

    a = plan(noise={"aim": np.float64(0.002)}, bounds={"speed": np.array([0.3, 6.0])},
             tolerance=np.float32(0.001))
    b = plan(noise={"aim": 0.002}, bounds={"speed": (0.3, 6.0)})
    assert a.best == b.best


def test_the_command_lines_whole_noise_spellings_are_taken():
    # "0" and "standard*2" are `--noise` spellings; Python refused them (only "standard", the
    # number 0 and a dict were taken).
    def doc(noise):
        d = plan(noise=noise).to_dict()
        del d["wall_time"]
        return d

    twice = {k: 2.0 * v for k, v in snooker._snooker.STANDARD_NOISE.items()}
    assert doc("standard*2") == doc(twice)
    assert doc("standard*2")["best"]["robustness"]["noise"]["speed"] == 0.15
    assert doc("0") == doc(0)
    assert doc("standard*1") == doc("standard")


def test_plan_takes_a_huge_finite_noise_as_the_command_line_does():
    # `snooker plan --noise aim=1e300` is taken (any finite deviation >= 0 is played), so the
    # Python API takes it too; nothing of the plan is NaN.
    doc = plan(noise={"aim": 1e300}).to_dict()
    assert "nan" not in repr(doc).lower()


@pytest.mark.parametrize("call, kw, error, message", [
    ("impact_ball_ball", {"params": [1]}, TypeError, r"params: a dict"),
    ("impact_cushion", {"params": "mu_ball=0.06"}, TypeError, r"params: a dict"),
    ("impact_ball_ball", {"params": {"mu_ball": "x"}}, TypeError, r"params\['mu_ball'\]: a number"),
    ("impact_ball_ball", {"speed": "x"}, TypeError, r"speed: a number"),
    ("impact_cushion", {"speed": True}, TypeError, r"speed: a number"),
    ("impact_ball_ball", {"cut": "10"}, TypeError, r"cut: a number"),
    ("impact_cushion", {"angle": None}, TypeError, r"angle: a number"),
    ("impact_cushion", {"topspin": [1.0]}, TypeError, r"topspin: a number"),
    ("impact_ball_ball", {"sidespin": "1"}, TypeError, r"sidespin: a number"),
])
def test_impact_reports_refuse_a_malformed_argument_naming_it(call, kw, error, message):
    # Before: AttributeError "'list' object has no attribute 'items'", "could not convert
    # string to float: 'x'" naming no argument, True as 1 m/s.
    with pytest.raises(error, match="^" + message):
        getattr(snooker, call)(**{"speed": 1.0, **kw})


@pytest.mark.parametrize("times, error", [
    ([[0.0, 0.1]], ValueError), ([[0.0], [0.1]], ValueError),
    ([True, False], TypeError), ("0.1", TypeError), ([0.0, "x"], TypeError), (None, TypeError),
    ([[0.0, 0.1], [0.2]], TypeError),
])
def test_positions_refuses_times_that_are_not_one_number_or_a_1d_sequence(times, error):
    # Before: a 2-D array of times was flattened silently (positions of shape (4, n, 3) for
    # a (2, 2) array), True was 1 s, and a string said "could not convert string to float".
    shot = snooker.simulate(SCENE)
    with pytest.raises(error, match="^times: a number or a 1-D sequence"):
        shot.positions(times)


def test_positions_refuses_a_2d_array_of_times():
    import numpy as np

    shot = snooker.simulate(SCENE)
    with pytest.raises(ValueError, match=r"^times: .* not an array of shape \(2, 2\)"):
        shot.positions(np.full((2, 2), 0.1))


def test_positions_takes_one_number_a_list_or_a_1d_array():
    import numpy as np

    shot = snooker.simulate(SCENE)
    n = len(shot.ball_ids)
    assert shot.positions(0.1).shape == (1, n, 3)
    assert shot.positions(np.float32(0.1)).shape == (1, n, 3)
    both = shot.positions(np.array([0.0, 0.1]))
    assert both.shape == (2, n, 3)
    assert (shot.positions([0, 0.1]) == both).all()


@pytest.mark.parametrize("path, value, key", [
    (("cue", "speed"), True, "cue.speed"),
    (("cue", "offset"), [0.0, True], "cue.offset[1]"),
    (("balls", 0, "pos"), [False, 0.8], "balls[0].pos[0]"),
    (("balls", 1, "vel"), [0.1, True, 0.0], "balls[1].vel[1]"),
    (("params", "mu_roll"), True, "params.mu_roll"),
    (("sim", "max_time"), True, "sim.max_time"),
])
def test_a_dict_scene_refuses_a_bool_where_a_number_goes_as_the_files_do(path, value, key):
    # Before: {"cue": {"speed": True}} simulated at 1 m/s, where the TOML and JSON readers
    # refuse `speed = true` ("invalid type: boolean `true`, expected f64" at its key).
    import copy

    d = copy.deepcopy({**SCENE, "params": {}, "sim": {}})
    where = d
    for k in path[:-1]:
        where = where[k]
    where[path[-1]] = value
    reason = "invalid type: boolean `(true|false)`, expected f64"
    with pytest.raises(ValueError, match=f"^scene: key `{re.escape(key)}`: {reason}"):
        snooker.simulate(d)
    # The same scene as JSON text is refused in the same words.
    with pytest.raises(ValueError, match=f"key `{re.escape(key)}`: {reason}"):
        snooker._snooker.parse_json(json.dumps(d), "scene")


@pytest.mark.parametrize("key", ["to_play", "first_player"])
def test_a_dict_frame_refuses_a_bool_for_a_number_and_takes_its_bools(key):
    # Before: {"frame": {"to_play": True}} was player 1, where a frame file refuses it. The
    # frame table's own bools (ball_in_hand, free_ball) stay welcome.
    tomllib = pytest.importorskip("tomllib")
    doc = tomllib.loads(snooker.Frame.break_off().to_toml(STRIKE))
    doc["frame"]["ball_in_hand"] = False
    doc["frame"][key] = True
    with pytest.raises(ValueError, match=f"^frame: key `frame.{key}`: invalid type: boolean"):
        snooker.frame(doc)
    doc["frame"][key] = 1
    assert snooker.frame(doc).ball_in_hand is False


def test_a_dict_scene_refuses_a_pair_with_a_third_value():
    # As before, and as in a file: a tuple too long is refused, not cut short.
    with pytest.raises(ValueError, match=r"^scene: key `balls\[0\].pos`: invalid length 3"):
        snooker.scene({"balls": [{"id": "cue", "pos": (1.0, 0.8, 0.0)}]})


@pytest.mark.parametrize("read, what", [
    (snooker.simulate, "scene"), (snooker.scene, "scene"), (snooker.frame, "frame"),
    (snooker.Frame.load, "frame"),
])
def test_an_empty_path_is_refused_as_empty(read, what):
    # Before: ": cannot read the scene file: No such file or directory", naming nothing.
    with pytest.raises(ValueError, match=f"^path: empty, not the path of a {what} file"):
        read("")


@pytest.mark.parametrize("scenes", ["scenes/break-off.toml", SCENE])
def test_simulate_many_refuses_one_scene_for_a_list(scenes):
    # Before: a path was read character by character ("s: cannot read the scene file"), a
    # dict by its keys.
    with pytest.raises(TypeError, match="^scenes: a sequence of scenes"):
        snooker.simulate_many(scenes)


def test_simulate_many_names_a_bad_scene_by_its_index_and_its_results_as_simulate_does():
    # Before: a path that could not be read was named by the message alone, and an unnamed
    # scene's result was called "scenes[0]" where simulate calls it "scene".
    with pytest.raises(ValueError, match=r"^scenes\[1\]: "):
        snooker.simulate_many([SCENE, "no/such/scene.toml"])
    assert snooker.simulate_many([SCENE])[0].result == snooker.simulate(SCENE).result


def test_a_path_with_an_equals_sign_is_a_path(tmp_path):
    # Before: "runs/speed=2/s.toml" was read as TOML text: "not valid TOML (line 1, column 1)".
    d = tmp_path / "speed=2"
    d.mkdir()
    path = d / "s.toml"
    path.write_text('balls = [{id = "cue", pos = [1.0, 0.8]}]\n')
    assert snooker.simulate(str(path)).final["cue"].motion == "stationary"
    # TOML text on one line is still text.
    assert isinstance(snooker.scene('balls = [{id = "cue", pos = [1.0, 0.8]}]'), snooker.Scene)


@pytest.mark.parametrize("noise", [{"offset": 0.001, "speed": 0.1}])
def test_play_and_choose_refuse_the_old_noise_spelling_as_plan_does(noise):
    # Before: play and choose read speed=0.1 as 0.1 m/s where the old spelling meant a tenth
    # of the cue speed; plan and the command line refused it.
    f = snooker.Frame.open_table(1, 2)
    for call in (snooker.play, snooker.choose):
        with pytest.raises(ValueError, match="^noise: the old spelling"):
            call(f, noise=noise, effort=10)


def test_play_names_a_bad_noise_key_as_plan_does():
    # Before: "noise: noise.aim: ..." from play and choose, "noise['aim']: ..." from plan.
    f = snooker.Frame.open_table(1, 2)
    with pytest.raises(ValueError, match=r"^noise\['aim'\]: expected a finite number >= 0"):
        snooker.play(f, noise={"aim": -1.0}, effort=10)


@pytest.mark.parametrize("call, error, message", [
    (lambda f: f.with_cue_ball_at((True, 0.9)), TypeError, r"^pos: two numbers"),
    (lambda f: f.with_cue_ball_at((0.7, 0.9, 0.0)), ValueError,
     r"^pos: two numbers \(x, y\), got 3"),
    (lambda f: f.nearest_placement((1, 2, 3)), ValueError, r"^preferred: two numbers"),
    (lambda f: f.nearest_placement("xy"), TypeError, r"^preferred: two numbers"),
    (lambda f: f.play(STRIKE, cue_ball=(0.7, 0.9, 0.0)), ValueError, r"^cue_ball: two numbers"),
    (lambda f: f.play(STRIKE, cue_ball=(True, 0.9)), TypeError, r"^cue_ball: two numbers"),
])
def test_a_place_that_is_not_two_numbers_is_refused_naming_the_argument(call, error, message):
    # Before: True was taken as 1.0 (and the place blamed for lying outside the D), and three
    # numbers raised "expected a sequence of length 2 (got 3)", naming no argument.
    f = snooker.Frame.break_off()
    with pytest.raises(error, match=message):
        call(f)


def test_play_takes_a_bool_for_visit_and_nothing_else():
    # Before: visit="no" played a visit (bool("no") is True).
    with pytest.raises(TypeError, match="^visit: True or False"):
        snooker.play(snooker.Frame.open_table(1, 2), visit="no", effort=10)


def test_plan_takes_the_kinds_of_pot_as_the_command_line_does():
    scene = {"balls": [{"id": "cue", "pos": [1.0, 0.9]}, {"id": "red", "pos": [2.5, 1.2]}]}
    args = dict(cue_to=(1.5, 0.5), samples=4)
    direct = snooker.plan(scene, "red", "top-left", kinds=["direct"], **args)
    assert all(s.route.kind == "direct" for s in [direct.best] + list(direct.alternatives))
    with pytest.raises(ValueError, match="^kinds: unknown kind 'bank'"):
        snooker.plan(scene, "red", "top-left", kinds=["bank"], **args)
    with pytest.raises(TypeError, match="^kinds: a list"):
        snooker.plan(scene, "red", "top-left", kinds="direct", **args)


def test_the_exceptions_pickle_for_worker_processes():
    # Before: made in a module "_snooker" that cannot be imported: PicklingError.
    import pickle

    for cls in (snooker.SimulationError, snooker.CannotPot):
        e = pickle.loads(pickle.dumps(cls("why")))
        assert type(e) is cls and e.args == ("why",)
