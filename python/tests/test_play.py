"""The player from Python: ``snooker.play`` (strokes as objects, each replaying through the
rules as its line says, the same seed giving the same strokes), ``snooker.choose`` and the
baseline agent of examples/player_agent.py in the Gymnasium environment."""

import pathlib
import sys

import numpy as np
import pytest

import snooker

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "python" / "examples"))
from frame_env import SnookerFrameEnv  # noqa: E402
from player_agent import PlayerAgent, action_of  # noqa: E402

EFFORT = 400


def played(stroke):
    """The stroke's executed strike played from its frame: (verdict, next frame)."""
    s = stroke.executed.to_dict()
    s.pop("ball")
    return snooker.frame(stroke.frame).play(s)


def test_every_stroke_replays_from_its_frame_with_its_executed_strike():
    strokes = snooker.play(snooker.Frame.open_table(4, 5), seed=3, effort=EFFORT, visit=False,
                           max_strokes=6)
    assert 1 <= len(strokes) <= 6
    for k, s in enumerate(strokes):
        assert isinstance(s, snooker.Stroke) and s.stroke == k + 1
        assert s.plan.kind in ("direct", "double", "plant", "kiss", "safety")
        verdict, after = played(s)
        assert verdict.potted == s.referee["potted"]
        assert verdict.points == s.points and list(verdict.scores) == s.referee["scores"]
        assert verdict.foul == s.foul
        if k + 1 < len(strokes):
            nxt = snooker.frame(strokes[k + 1].frame)
            assert after is not None
            assert nxt.scores == after.scores and nxt.to_play == after.to_play
            assert nxt.on == after.on or nxt.nominated is not None
        # The line back as the play log writes it.
        d = s.to_dict()
        assert list(d)[:8] == ["stroke", "player", "frame", "nominated", "intended",
                               "executed", "plan", "referee"]
        assert snooker.Stroke.from_dict(d) == s


def test_the_same_seed_gives_the_same_strokes_and_noise_zero_plays_the_strike_meant():
    frame = snooker.Frame.open_table(3, 8)
    a = snooker.play(frame, seed=4, effort=EFFORT)
    b = snooker.play(frame, seed=4, effort=EFFORT)
    strip = lambda ss: [(s.frame, s.intended, s.executed, s.referee) for s in ss]  # noqa: E731
    assert strip(a) == strip(b)
    quiet = snooker.play(frame, noise=0, seed=4, effort=EFFORT)
    assert all(s.executed == s.intended for s in quiet)
    assert any(s.executed != s.intended for s in a)


def test_choose_places_the_cue_ball_in_hand_and_refuses_bad_arguments():
    frame = snooker.Frame.break_off()
    d = snooker.choose(frame, effort=EFFORT)
    assert isinstance(d, snooker.Decision) and d.cue_ball is not None
    (cx, cy), radius = frame.the_d
    assert np.hypot(d.cue_ball[0] - cx, d.cue_ball[1] - cy) <= radius + 1e-9
    assert d.cue_ball[0] <= cx + 1e-9
    with pytest.raises(ValueError, match="noise\\['spin'\\]"):
        snooker.choose(frame, noise={"spin": 0.1})
    with pytest.raises(ValueError, match="effort"):
        snooker.play(frame, effort=0)
    with pytest.raises(ValueError, match="opponent"):
        snooker.play(frame, opponent="nobody", visit=False)


def test_the_player_as_a_gymnasium_agent_plays_the_strike_it_chose():
    env = SnookerFrameEnv(reds=3, episode="visit")
    env.reset(seed=2)
    agent = PlayerAgent(env, effort=EFFORT)
    frame = env.frame
    action = agent(None)
    assert env.action_space.contains(action)
    # The action maps back onto the decision's strike.
    speed, aim, side, height, elevation = env.physical(action)[:5]
    s = agent.decision.strike
    assert speed == pytest.approx(s.speed, abs=1e-9)
    assert np.cos(aim - s.aim) == pytest.approx(1.0, abs=1e-12)
    assert (side, height, elevation) == pytest.approx((*s.offset, s.elevation), abs=1e-9)
    assert np.array_equal(action, action_of(frame, agent.decision))
    # With the cue ball not in hand and no colour to nominate, the step plays exactly that
    # strike: the verdict is the one the frame gives it.
    _, reward, _, _, info = env.step(action)
    verdict, _ = frame.play({"speed": float(speed), "aim": float(aim),
                             "offset": [float(side), float(height)],
                             "elevation": float(elevation)})
    assert info["potted"] == verdict.potted and reward == verdict.points - verdict.foul_points


@pytest.mark.parametrize("call", [
    "snooker.play(snooker.Frame.open_table(15, 7), visit=False, max_strokes=300, noise=0)",
    "snooker.plan('scenes/chapter7-example.toml', 'red', 'middle-left', (1.25, 0.0262), "
    "samples=1000000, alternatives=1000)",
])
def test_ctrl_c_stops_a_long_call(call):
    # Before: the interrupt reached Python only when the call returned (32 s later for a
    # frame, minutes for a plan of a million samples); now the search stops within a batch of
    # shots. The call runs in a child process sent SIGINT once it is under way; it must end
    # with KeyboardInterrupt well before the call could have finished.
    import signal
    import subprocess
    import time

    root = pathlib.Path(__file__).resolve().parents[2]
    # The child takes Python's own Ctrl-C handler whatever it inherits: a test command started
    # in the background of a shell without job control (nohup, CI runners) has SIGINT ignored,
    # which Python then leaves ignored, and the interrupt never arrived (stop 42's fresh clone).
    code = ("import signal, snooker, sys\n"
            "signal.signal(signal.SIGINT, signal.default_int_handler)\n"
            "print('started', flush=True)\n"
            f"try:\n    {call}\nexcept KeyboardInterrupt:\n    print('interrupted')\n"
            "    sys.exit(3)\n")
    child = subprocess.Popen([sys.executable, "-c", code], cwd=root, stdout=subprocess.PIPE,
                             text=True)
    assert child.stdout.readline().strip() == "started"
    time.sleep(2.0)
    child.send_signal(signal.SIGINT)
    try:
        out, _ = child.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        child.kill()
        raise AssertionError("the call went on a minute after Ctrl-C")
    assert child.returncode == 3 and "interrupted" in out, (child.returncode, out)
