"""The Gymnasium-style example environment (examples/gym_env.py): a straight pot is rewarded
and the potted ball leaves the observation."""

import math
import pathlib
import sys

import numpy as np
import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "examples"))
from gym_env import SnookerEnv  # noqa: E402


def test_a_straight_pot_is_rewarded():
    env = SnookerEnv(reds=1)
    obs, _ = env.reset(seed=4)
    assert obs.shape == (2, 2)
    # The red on the line from the cue ball to the top-left corner pocket.
    env.balls = {"cue": (3.2, 1.4), "red1": (3.4, 1.6)}
    obs, reward, terminated, truncated, info = env.step([2.0, math.pi / 4, 0.0, 0.0, 0.0])
    assert info["potted"] == ["red1"] and reward == 1.0 and terminated and not truncated
    assert obs[1].tolist() == [-1.0, -1.0] and np.all(obs[0] > 0)


def test_random_play_keeps_the_observation_on_the_table():
    env = SnookerEnv(reds=3, max_shots=5)
    obs, _ = env.reset(seed=2)
    done = False
    while not done:
        obs, reward, terminated, truncated, _ = env.step(env.rng.uniform([0.5, -3, 0, 0, 0], [6, 3, 0, 0, 0]))
        done = terminated or truncated
        on = obs[obs[:, 0] >= 0]
        assert np.all(on[:, 0] <= 3.569) and np.all(on[:, 1] <= 1.778)
    assert env.shots <= 5


def test_the_environment_passes_gymnasiums_checker_and_a_seed_repeats_an_episode():
    # Before: check_env failed, "Expects the random number generator to have been generated
    # given a seed was passed to reset" (reset seeded its own generator, not np_random).
    import warnings

    from gymnasium.utils.env_checker import check_env

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # its advice on the action's (physical) bounds
        check_env(SnookerEnv(reds=2), skip_render_check=True)

    def episode(seed):
        env = SnookerEnv(reds=2, max_shots=3)
        out = [env.reset(seed=seed)[0]]
        env.action_space.seed(seed)
        for _ in range(3):
            obs, reward, terminated, truncated, _ = env.step(env.action_space.sample())
            out.append((obs, reward))
            if terminated or truncated:
                break
        return out

    a, b = episode(7), episode(7)
    assert np.array_equal(a[0], b[0])
    assert all(np.array_equal(x[0], y[0]) and x[1] == y[1] for x, y in zip(a[1:], b[1:]))


@pytest.mark.parametrize("action", [[1.0], [1.0] * 6, [np.nan, 0, 0, 0, 0], [np.inf, 0, 0, 0, 0],
                                    np.zeros((2, 5)), "abcde", None, np.array([True] * 5),
                                    np.array([2, 0, 0, 0, 0], complex)])
def test_an_action_of_the_wrong_shape_or_not_finite_is_refused(action):
    # Before: [1.0] was broadcast to all five components and played (speed 1, aim 1 rad, ...);
    # a NaN came back as the scene's "key `cue.speed`", six numbers as a broadcasting error;
    # bools were played as 1 and 0, a complex action with its imaginary part dropped.
    env = SnookerEnv(reds=1)
    env.reset(seed=1)
    with pytest.raises(ValueError, match="^action: 5 finite numbers"):
        env.step(action)


def test_a_step_before_reset_asks_for_reset():
    # Before: "scene: ... the scene has no balls", the scene's message for an empty table.
    from gymnasium.error import ResetNeeded

    with pytest.raises(ResetNeeded, match=r"^step: call reset\(\) first"):
        SnookerEnv(reds=1).step([2.0, 0.0, 0.0, 0.0, 0.0])


@pytest.mark.parametrize("kw, error", [
    ({"reds": -1}, ValueError), ({"reds": 16}, ValueError), ({"reds": 2.0}, TypeError),
    ({"reds": True}, TypeError), ({"max_shots": 0}, ValueError), ({"max_shots": "5"}, TypeError),
])
def test_a_bad_count_is_refused_naming_it(kw, error):
    # Before: reds=-1 was an environment of 0 reds without a word, reds=True one red,
    # reds=2.0 a TypeError of range() naming nothing, max_shots=0 an episode of one shot. At
    # most 15 reds, as Frame.open_table racks.
    (name,) = kw
    with pytest.raises(error, match=f"^{name}: "):
        SnookerEnv(**kw)


def test_the_potted_cue_ball_comes_back_to_a_free_place():
    # Before: with the brown spot taken, the cue ball went to (0.5, 0.5) unchecked, onto a red
    # there; the observation showed two balls in one place and every later step raised.
    from gym_env import BROWN_SPOT, R

    env = SnookerEnv(reds=2)
    env.reset(seed=4)
    env.balls = {"cue": (3.2, 1.4), "red1": BROWN_SPOT, "red2": (0.5, 0.5)}
    obs, reward, *_ = env.step([2.0, math.atan2(1.778 - 1.4, 3.569 - 3.2), 0, 0, 0])
    assert reward == -1.0  # the in-off
    places = [tuple(p) for p in obs if tuple(p) != (-1.0, -1.0)]
    assert len(places) == 3
    assert all(math.dist(p, q) >= 2 * R for i, p in enumerate(places) for q in places[:i])
    env.step([1.0, 0.0, 0.0, 0.0, 0.0])  # the episode goes on
