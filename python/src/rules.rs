//! Snooker by the rules from Python: `snooker.Frame` (a frame between strokes, its attributes
//! read from the rules crate's typed frame) and `snooker.Verdict` (the referee's verdict on a
//! stroke). A stroke is simulated with the GIL released, then judged.

use crate::{Shot, SimulationError, bad_scene};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyMapping, PyString, PyTuple};
use snooker_engine::Cue;
use snooker_rules::{Colour, Frame as RulesFrame, FrameError, Next, Verdict as V};
use snooker_scene::{Scene, StruckBall};
use std::path::PathBuf;
use std::sync::Arc;

fn bad_frame(e: FrameError) -> PyErr {
    PyValueError::new_err(e.to_string())
}

fn colour(name: &str) -> PyResult<Colour> {
    Colour::from_name(name).ok_or_else(|| {
        PyValueError::new_err(format!(
            "nominated: \"{name}\" is not a colour (yellow, green, brown, blue, pink, black)"
        ))
    })
}

/// A frame of snooker between strokes: the balls at rest, the ball on, the scores, whose turn.
#[pyclass(frozen, module = "snooker._snooker", name = "Frame")]
pub struct Frame(pub RulesFrame);

/// The referee's verdict on one stroke.
#[pyclass(frozen, module = "snooker._snooker", name = "Verdict")]
pub struct Verdict {
    verdict: V,
    shot: Py<Shot>,
    /// The frame the stroke was judged on (the player's choices applied).
    judged: RulesFrame,
}

/// The keys a strike dict may have: the scene file's `[cue]` keys.
const STRIKE_KEYS: [&str; 5] = ["ball", "speed", "aim", "offset", "elevation"];

/// A strike from a dict with the scene file's `[cue]` keys (speed, aim, offset, elevation;
/// `ball`, if given, must name the frame's cue ball `cue_id`): any other key, a value that is
/// not a number (a bool included) or a strike that is not a mapping is refused, naming it.
fn strike(d: &Bound<'_, PyAny>, cue_id: &str) -> PyResult<Cue> {
    let map = d.cast::<PyMapping>().map_err(|_| {
        PyTypeError::new_err(format!(
            "strike: a dict with the keys speed, aim, offset, elevation, not {}",
            type_name(d)
        ))
    })?;
    for key in map.keys()?.iter() {
        let name = key.extract::<String>().unwrap_or_else(|_| key.to_string());
        if !STRIKE_KEYS.contains(&name.as_str()) {
            return Err(PyValueError::new_err(format!(
                "strike: unknown key `{name}` (speed, aim, offset, elevation; or ball)"
            )));
        }
    }
    if let Some(ball) = item(map, "ball")? {
        let id = ball.extract::<String>().ok();
        if id.as_deref() != Some(cue_id) {
            return Err(PyValueError::new_err(format!(
                "strike: `ball` is {}, not the cue ball \"{cue_id}\" (the strike is on the cue ball)",
                ball.repr()?
            )));
        }
    }
    let offset = match item(map, "offset")? {
        None => [0.0, 0.0],
        Some(v) => match v.extract::<[Bound<'_, PyAny>; 2]>() {
            Ok([side, height]) => [
                number(&side, "offset[0]").map_err(|_| bad_offset())?,
                number(&height, "offset[1]").map_err(|_| bad_offset())?,
            ],
            Err(_) => return Err(bad_offset()),
        },
    };
    let num = |k: &str, default: Option<f64>| -> PyResult<f64> {
        match (item(map, k)?, default) {
            (Some(v), _) => number(&v, k),
            (None, Some(x)) => Ok(x),
            (None, None) => Err(PyValueError::new_err(format!("strike: `{k}` is missing"))),
        }
    };
    Ok(Cue {
        speed: num("speed", None)?,
        aim: num("aim", None)?,
        offset,
        elevation: num("elevation", Some(0.0))?,
    })
}

/// The value of `key` in a strike, or None when it is not there.
fn item<'py>(map: &Bound<'py, PyMapping>, key: &str) -> PyResult<Option<Bound<'py, PyAny>>> {
    if map.contains(key)? {
        map.get_item(key).map(Some)
    } else {
        Ok(None)
    }
}

/// A strike's number (a Python or NumPy float or int; not a bool).
fn number(v: &Bound<'_, PyAny>, key: &str) -> PyResult<f64> {
    let not = || PyValueError::new_err(format!("strike: `{key}` must be a number"));
    if v.is_instance_of::<PyBool>() || v.is_instance_of::<PyString>() {
        return Err(not());
    }
    v.extract::<f64>().map_err(|_| not())
}

fn bad_offset() -> PyErr {
    PyValueError::new_err("strike: `offset` must be two numbers [side, height]")
}

/// A Python object's type name, for messages.
fn type_name(v: &Bound<'_, PyAny>) -> String {
    v.get_type()
        .name()
        .map_or_else(|_| "that".into(), |n| n.to_string())
}

/// The id of `frame`'s cue ball ("cue" when it has none on the table).
fn cue_id(frame: &RulesFrame) -> String {
    frame
        .cue_index()
        .map_or("cue".to_string(), |i| frame.balls()[i].id.clone())
}

/// Checks `cue` as the engine would strike the cue ball with it (speed, aim, offset and
/// elevation within the engine's limits), naming the `[cue]` key at fault.
fn check_strike(frame: &RulesFrame, cue: &Cue) -> PyResult<()> {
    let r = frame.params().ball_radius;
    let ball = snooker_engine::BallState::at_rest(0.0, 0.0, r);
    snooker_engine::cue::strike(&ball, cue, frame.params())
        .map(|_| ())
        .map_err(|e| PyValueError::new_err(format!("key `cue.{}`: {}", e.key, e.reason)))
}

#[pymethods]
impl Frame {
    /// Reads a frame file (a scene file with a `[frame]` table); its `[cue]`, if any, is not
    /// part of the frame.
    #[staticmethod]
    fn load(path: PathBuf) -> PyResult<Frame> {
        crate::not_empty(&path, "frame")?;
        snooker_rules::load(&path)
            .map(|f| Frame(f.frame))
            .map_err(bad_scene)
    }

    /// Reads frame TOML text; `name` names it in error messages.
    #[staticmethod]
    #[pyo3(signature = (text, name="frame"))]
    fn from_toml(text: &str, name: &str) -> PyResult<Frame> {
        snooker_rules::parse(text, name)
            .map(|f| Frame(f.frame))
            .map_err(bad_scene)
    }

    /// Reads a frame given as JSON text (an object with the frame file's keys).
    #[staticmethod]
    #[pyo3(signature = (text, name="frame"))]
    fn from_json(text: &str, name: &str) -> PyResult<Frame> {
        snooker_rules::parse_json(text, name)
            .map(|f| Frame(f.frame))
            .map_err(bad_scene)
    }

    /// A frame from a dict with the frame file's keys (`frame`, `balls`, `layout`, ...; lists,
    /// numbers and strings as its values), checked by the rules crate as a file is.
    #[staticmethod]
    #[pyo3(signature = (source, name="frame"))]
    fn from_dict(source: &Bound<'_, PyAny>, name: &str) -> PyResult<Frame> {
        snooker_rules::from_value(crate::strict::Strict(source.clone()), name)
            .map(|f| Frame(f.frame))
            .map_err(bad_scene)
    }

    /// The start of a frame: the rack, the colours on their spots, the cue ball in hand in
    /// the D, player 0 to break off.
    #[staticmethod]
    fn break_off() -> Frame {
        Frame(RulesFrame::break_off())
    }

    /// An open table: `reds` reds (0 to 15) and the cue ball at random places (the same
    /// `seed`, a whole number in [0, 2^64), the same frame), the colours on their spots, reds
    /// on, player 0 to play. Other counts and seeds are refused (ValueError, TypeError).
    #[staticmethod]
    #[pyo3(signature = (reds=None, seed=None), text_signature = "(reds=15, seed=0)")]
    fn open_table(
        reds: Option<&Bound<'_, PyAny>>,
        seed: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Frame> {
        let reds = reds.map_or(Ok(15), |r| crate::whole(r, "reds", 15))?;
        let seed = seed.map_or(Ok(0), |s| crate::whole(s, "seed", u64::MAX))?;
        Ok(Frame(RulesFrame::open_table(reds as usize, seed)))
    }

    /// The frame's name.
    #[getter]
    fn name(&self) -> &str {
        self.0.name()
    }

    /// The ball on: "red", "colour", or a colour of the closing sequence.
    #[getter]
    fn on(&self) -> &'static str {
        self.0.state().on.name()
    }

    /// The colour nominated for the stroke, or None.
    #[getter]
    fn nominated(&self) -> Option<&'static str> {
        self.0.state().nominated.map(Colour::name)
    }

    /// Points of player 0 and player 1.
    #[getter]
    fn scores(&self) -> (u32, u32) {
        let s = self.0.state().scores;
        (s[0], s[1])
    }

    /// The player at the table (0 or 1).
    #[getter]
    fn to_play(&self) -> u8 {
        self.0.state().to_play
    }

    /// Who played the first stroke of the frame.
    #[getter]
    fn first_player(&self) -> u8 {
        self.0.state().first_player
    }

    /// True when the cue ball is in hand (to be placed in the D).
    #[getter]
    fn ball_in_hand(&self) -> bool {
        self.0.state().ball_in_hand
    }

    /// True when the player was awarded a free ball.
    #[getter]
    fn free_ball(&self) -> bool {
        self.0.state().free_ball
    }

    /// The balls on the table by id: (x, y) of the centre, m, in the frame's order.
    #[getter]
    fn balls<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for b in self.0.balls() {
            d.set_item(&b.id, (b.state.pos.x, b.state.pos.y))?;
        }
        Ok(d)
    }

    /// The balls' kinds by id: "cue", "red", or a colour.
    #[getter]
    fn kinds<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for b in self.0.balls() {
            let kind = match Colour::of(b.kind) {
                Some(c) => c.name(),
                None if b.kind == snooker_engine::BallKind::Red => "red",
                None => "cue",
            };
            d.set_item(&b.id, kind)?;
        }
        Ok(d)
    }

    /// The ids of the balls on for the stroke (with a colour or a free ball on and nothing
    /// nominated: every ball that could be nominated).
    #[getter]
    fn balls_on(&self) -> Vec<String> {
        self.0
            .balls_on()
            .into_iter()
            .map(|i| self.0.balls()[i].id.clone())
            .collect()
    }

    /// The colours the player may nominate.
    #[getter]
    fn legal_nominations(&self) -> Vec<&'static str> {
        self.0
            .legal_nominations()
            .into_iter()
            .map(Colour::name)
            .collect()
    }

    /// The D: ((x, y) of its centre, radius), m.
    #[getter]
    fn the_d(&self) -> ((f64, f64), f64) {
        let d = self.0.the_d();
        ((d.centre.x, d.centre.y), d.radius)
    }

    /// The ball radius, m.
    #[getter]
    fn ball_radius(&self) -> f64 {
        self.0.params().ball_radius
    }

    /// The valid place for the cue ball in hand nearest `preferred` (x, y), or None.
    /// A non-finite `preferred` is refused (ValueError).
    fn nearest_placement(&self, preferred: &Bound<'_, PyAny>) -> PyResult<Option<(f64, f64)>> {
        let preferred = crate::point(preferred, "preferred")?;
        if !preferred.iter().all(|v| v.is_finite()) {
            return Err(PyValueError::new_err(format!(
                "preferred: must be two finite numbers (x, y), got ({}, {})",
                preferred[0], preferred[1]
            )));
        }
        Ok(self.0.nearest_placement(preferred).map(|p| (p[0], p[1])))
    }

    /// This frame with `nominated` (a colour's name, or None) nominated; None with a free
    /// ball declines it (the ball on is played, `free_ball` false).
    #[pyo3(signature = (nominated))]
    fn with_nomination(&self, nominated: Option<&str>) -> PyResult<Frame> {
        let c = nominated.map(colour).transpose()?;
        self.0.with_nomination(c).map(Frame).map_err(bad_frame)
    }

    /// This frame with the cue ball in hand placed at `pos` (x, y): refused (ValueError)
    /// outside the D or touching a ball.
    fn with_cue_ball_at(&self, pos: &Bound<'_, PyAny>) -> PyResult<Frame> {
        self.0
            .with_cue_ball_at(crate::point(pos, "pos")?)
            .map(Frame)
            .map_err(bad_frame)
    }

    /// Plays `strike` (a dict with the `[cue]` keys: speed, aim, offset, elevation) on the cue
    /// ball, the simulation with the GIL released: returns (verdict, next frame or None when
    /// the frame is over). `nominated` and `cue_ball` (x, y in the D, with the cue ball in
    /// hand) are the player's choices for the stroke.
    #[pyo3(signature = (strike, nominated=None, cue_ball=None))]
    fn play<'py>(
        &self,
        py: Python<'py>,
        strike: &Bound<'py, PyAny>,
        nominated: Option<&str>,
        cue_ball: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let cue = self::strike(strike, &cue_id(&self.0))?;
        let mut frame = self.0.clone();
        if let Some(p) = cue_ball {
            let p = crate::point(p, "cue_ball")?;
            frame = frame.with_cue_ball_at(p).map_err(bad_frame)?;
        }
        if let Some(n) = nominated {
            frame = frame.with_nomination(Some(colour(n)?)).map_err(bad_frame)?;
        }
        let setup = frame.setup(&cue).map_err(bad_frame)?;
        let index = frame.cue_index().unwrap_or(0);
        let before = frame.balls()[index].state;
        let struck = snooker_engine::cue::strike(&before, &cue, frame.params())
            .map_err(|e| PyValueError::new_err(format!("cue.{e}")))?;
        let scene = Arc::new(Scene {
            name: frame.name().to_string(),
            setup,
            options: *frame.options(),
            strike: Some(StruckBall {
                id: frame.balls()[index].id.clone(),
                index,
                cue,
                strike: struck,
                before,
            }),
        });
        let sc = scene.clone();
        let shot = py
            .detach(|| snooker_engine::simulate(&sc.setup, &sc.options))
            .map_err(|e| SimulationError::new_err(format!("{}: {e}", scene.name)))?;
        let verdict = frame.judge(&shot).map_err(|e| match e {
            snooker_rules::JudgeError::Frame(e) => bad_frame(e),
            e => SimulationError::new_err(e.to_string()),
        })?;
        let next = match frame.next(&verdict) {
            Next::Play(f) => Some(Py::new(py, Frame(*f))?.into_any()),
            Next::Over { .. } => None,
        };
        let v = Verdict {
            verdict,
            shot: Py::new(py, Shot { scene, shot })?,
            judged: frame,
        };
        PyTuple::new(
            py,
            [
                Py::new(py, v)?.into_any(),
                next.unwrap_or_else(|| py.None()),
            ],
        )
    }

    /// The frame file of this frame, with `strike` (a dict) as its `[cue]` if given: a strike
    /// the engine would refuse (as `play` does) is refused, so the file reads back.
    #[pyo3(signature = (strike=None))]
    fn to_toml(&self, strike: Option<&Bound<'_, PyAny>>) -> PyResult<String> {
        let cue = strike
            .map(|s| self::strike(s, &cue_id(&self.0)))
            .transpose()?;
        if let Some(c) = &cue {
            check_strike(&self.0, c)?;
        }
        Ok(self.0.to_toml(cue.as_ref()))
    }

    /// Pickling and `copy.deepcopy` (an environment's snapshot, a worker process): the frame
    /// travels as its frame file, which reads back to the same frame.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (String, String))> {
        let frame = &slf.get().0;
        let read = slf.get_type().getattr("from_toml")?;
        Ok((read, (frame.to_toml(None), frame.name().to_string())))
    }

    fn __repr__(&self) -> String {
        let s = self.0.state();
        format!(
            "<Frame {:?}: {} balls, player {} on {}, scores {}-{}>",
            self.0.name(),
            self.0.balls().len(),
            s.to_play,
            s.on,
            s.scores[0],
            s.scores[1]
        )
    }
}

#[pymethods]
impl Verdict {
    /// After a foul, the frame with the offender asked to play again from the position left
    /// (WPBSA Section 3 Rules 3(b) and 13; a free ball void, Rule 12); None after a legal
    /// stroke or a foul on the last black.
    fn play_again(&self) -> Option<Frame> {
        self.judged.play_again(&self.verdict).map(Frame)
    }

    /// After a foul, the frame before the stroke put back for the offender to play again with
    /// the foul's points scored (a foul and a miss, WPBSA Section 3 Rule 14: whether it was a
    /// miss is the caller's call); None where `play_again` is None.
    fn put_back(&self) -> Option<Frame> {
        self.judged.put_back(&self.verdict).map(Frame)
    }

    /// No foul.
    #[getter]
    fn legal(&self) -> bool {
        self.verdict.legal()
    }

    /// The foul's reason (formats.md's names), or None.
    #[getter]
    fn foul(&self) -> Option<&'static str> {
        self.verdict.foul.as_ref().map(|f| f.reason.name())
    }

    /// Every reason of the foul that applies, in the contract's order.
    #[getter]
    fn foul_reasons(&self) -> Vec<&'static str> {
        self.verdict
            .foul
            .as_ref()
            .map(|f| f.reasons.iter().map(|r| r.name()).collect())
            .unwrap_or_default()
    }

    /// Points of the foul, to the opponent (0 for a legal stroke).
    #[getter]
    fn foul_points(&self) -> u32 {
        self.verdict.foul_points()
    }

    /// The ball the cue ball hit first, or None.
    #[getter]
    fn first_hit(&self) -> Option<String> {
        self.verdict.first_hit.clone()
    }

    /// The object balls potted, in time order.
    #[getter]
    fn potted(&self) -> Vec<String> {
        self.verdict.potted.clone()
    }

    /// True when the cue ball went into a pocket.
    #[getter]
    fn cue_ball_potted(&self) -> bool {
        self.verdict.cue_ball_potted
    }

    /// The balls forced off the table.
    #[getter]
    fn off_table(&self) -> Vec<String> {
        self.verdict.off_table.clone()
    }

    /// Points scored by the player at the table.
    #[getter]
    fn points(&self) -> u32 {
        self.verdict.points
    }

    /// The scores after the stroke.
    #[getter]
    fn scores(&self) -> (u32, u32) {
        (self.verdict.scores[0], self.verdict.scores[1])
    }

    /// The colours respotted, in the order placed: (id, (x, y)).
    #[getter]
    fn respotted(&self) -> Vec<(String, (f64, f64))> {
        self.verdict
            .respotted
            .iter()
            .map(|(id, r)| (id.clone(), (r.pos.x, r.pos.y)))
            .collect()
    }

    /// True when the stroke ended the frame.
    #[getter]
    fn frame_over(&self) -> bool {
        self.verdict.frame_over()
    }

    /// The winner when the frame is over, else None.
    #[getter]
    fn winner(&self) -> Option<u8> {
        self.verdict.winner
    }

    /// The simulated stroke, a `snooker.Shot` (events, final states, positions at any time).
    #[getter]
    fn shot<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        py.import("snooker")?
            .getattr("Shot")?
            .call1((self.shot.clone_ref(py),))
    }

    /// The referee's result (formats.md, "Referee result") as JSON text, with the shot's
    /// result document as `shot` if `shot` is true.
    #[pyo3(signature = (shot=false))]
    fn to_json(&self, shot: bool) -> String {
        let doc = shot.then(|| {
            let s = self.shot.get();
            snooker_scene::result::result_record(&s.scene, &s.shot)
        });
        serde_json::to_string(&self.verdict.report(doc)).expect("JSON of finite numbers")
    }

    fn __repr__(&self) -> String {
        let v = &self.verdict;
        match &v.foul {
            None => format!(
                "<Verdict legal: potted {:?}, {} points, scores {}-{}>",
                v.potted, v.points, v.scores[0], v.scores[1]
            ),
            Some(f) => format!(
                "<Verdict foul {} ({} points): scores {}-{}>",
                f.reason, f.points, v.scores[0], v.scores[1]
            ),
        }
    }
}
