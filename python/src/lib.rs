//! The `snooker._snooker` extension module: scenes read by the scene crate, shots simulated by
//! the engine with the GIL released (many on rayon's threads), plans by the planner. The
//! Python layer (`snooker/__init__.py`) turns the JSON documents into dicts and the positions
//! into NumPy arrays; errors carry the command line's messages.

use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes};
use snooker_engine::SimError;
use snooker_planner::{Interval, PlanError, Request, RequestField, ShotKind, StrikeVariable};
use snooker_scene::impact_report::{Geometry, ImpactSpec, impact_report};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

mod interrupt;
mod noise;
mod play;
mod rules;
mod strict;

create_exception!(
    snooker._snooker,
    SimulationError,
    PyRuntimeError,
    "A valid scene that the engine could not simulate to its end (the event cap, the time \
     limit, or an internal error: please report the scene)."
);
create_exception!(
    snooker._snooker,
    CannotPot,
    PyRuntimeError,
    "No strike within the bounds pots the ball without a foul (blocked, snookered)."
);

/// A scene read and checked (the cue strike applied).
#[pyclass(frozen, module = "snooker._snooker")]
struct Scene(Arc<snooker_scene::Scene>);

#[pymethods]
impl Scene {
    /// The scene's name.
    #[getter]
    fn name(&self) -> &str {
        &self.0.name
    }

    /// The balls' ids, in the scene's order.
    #[getter]
    fn ball_ids(&self) -> Vec<String> {
        self.0.setup.balls.iter().map(|b| b.id.clone()).collect()
    }
}

fn bad_scene(e: snooker_scene::SceneError) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// Refuses an empty path, naming what file it should have named: the file readers would say
/// ": cannot read the scene file", naming nothing.
pub(crate) fn not_empty(path: &Path, what: &str) -> PyResult<()> {
    if path.as_os_str().is_empty() {
        return Err(PyValueError::new_err(format!(
            "path: empty, not the path of a {what} file"
        )));
    }
    Ok(())
}

/// Reads a scene file.
#[pyfunction]
fn load(path: PathBuf) -> PyResult<Scene> {
    not_empty(&path, "scene")?;
    snooker_scene::load(&path)
        .map(|s| Scene(Arc::new(s)))
        .map_err(bad_scene)
}

/// Reads scene TOML text; `file` names it in error messages.
#[pyfunction]
fn parse_toml(text: &str, file: &str) -> PyResult<Scene> {
    snooker_scene::parse(text, file)
        .map(|s| Scene(Arc::new(s)))
        .map_err(bad_scene)
}

/// Reads a scene given as JSON text (an object with the scene file's keys).
#[pyfunction]
fn parse_json(text: &str, file: &str) -> PyResult<Scene> {
    snooker_scene::parse_json(text, file)
        .map(|s| Scene(Arc::new(s)))
        .map_err(bad_scene)
}

/// Reads a scene given as a dict with the scene file's keys (lists, numbers and strings as
/// its values), checked by the scene crate as a file is: errors name the key (a bool where a
/// number is expected is refused, as in a file).
#[pyfunction]
fn parse_dict(source: &Bound<'_, PyAny>, file: &str) -> PyResult<Scene> {
    snooker_scene::parse_value(strict::Strict(source.clone()), file)
        .map(|s| Scene(Arc::new(s)))
        .map_err(bad_scene)
}

/// `v` as a point (x, y) in m: a sequence of exactly two numbers (not bools, which Python
/// would take as 1 and 0, nor a string), refused naming the argument `name`: `TypeError` for
/// the type, `ValueError` for the length.
pub(crate) fn point(v: &Bound<'_, PyAny>, name: &str) -> PyResult<[f64; 2]> {
    let not_a_point = || -> PyResult<PyErr> {
        Ok(PyTypeError::new_err(format!(
            "{name}: two numbers (x, y) in m, not {}",
            v.repr()?
        )))
    };
    if v.is_instance_of::<pyo3::types::PyString>() {
        return Err(not_a_point()?);
    }
    let Ok(items) = v.try_iter() else {
        return Err(not_a_point()?);
    };
    let items = items.collect::<PyResult<Vec<_>>>()?;
    if items.len() != 2 {
        return Err(PyValueError::new_err(format!(
            "{name}: two numbers (x, y), got {} of them",
            items.len()
        )));
    }
    let mut xy = [0.0; 2];
    for (slot, item) in xy.iter_mut().zip(&items) {
        if item.is_instance_of::<PyBool>() || item.is_instance_of::<pyo3::types::PyString>() {
            return Err(not_a_point()?);
        }
        *slot = item.extract::<f64>().or_else(|_| Err(not_a_point()?))?;
    }
    Ok(xy)
}

/// A whole-number argument `name` in [0, `max`]: a Python or NumPy int (not a bool, not a
/// float), refused naming the argument (TypeError for the type, ValueError for the range).
pub(crate) fn whole(v: &Bound<'_, PyAny>, name: &str, max: u64) -> PyResult<u64> {
    let py = v.py();
    let index = py.import("operator")?.getattr("index")?;
    let n = match index.call1((v,)) {
        Ok(n) if !v.is_instance_of::<PyBool>() => n,
        _ => {
            return Err(PyTypeError::new_err(format!(
                "{name}: a whole number, not {}",
                v.repr()?
            )));
        }
    };
    if n.lt(0)? || n.gt(max)? {
        return Err(PyValueError::new_err(format!(
            "{name}: must lie in [0, {max}], got {n}"
        )));
    }
    n.extract::<u64>()
}

/// A typed value as Python objects (dicts, lists, numbers, strings), no JSON text between.
fn to_python<'py, T: serde::Serialize>(py: Python<'py>, value: &T) -> PyResult<Bound<'py, PyAny>> {
    pythonize::pythonize(py, value).map_err(|e| PyRuntimeError::new_err(e.to_string()))
}

/// A simulated shot.
#[pyclass(frozen, module = "snooker._snooker")]
struct Shot {
    scene: Arc<snooker_scene::Scene>,
    shot: snooker_engine::Shot,
}

#[pymethods]
impl Shot {
    /// The result document of `snooker simulate --json`, as Python values.
    fn result<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(
            py,
            &snooker_scene::result::result_record(&self.scene, &self.shot),
        )
    }

    /// The balls' ids, in the scene's order.
    #[getter]
    fn ball_ids(&self) -> Vec<String> {
        self.shot.tracks.iter().map(|t| t.id.clone()).collect()
    }

    /// The scene's name.
    #[getter]
    fn scene_name(&self) -> &str {
        &self.scene.name
    }

    /// How many events the shot has.
    #[getter]
    fn event_count(&self) -> usize {
        self.shot.events.len()
    }

    /// The pots, as in the result document without reading it whole: (ball, pocket, t).
    fn pots(&self) -> Vec<(String, String, f64)> {
        snooker_scene::result::departures(&self.shot, snooker_engine::EventKind::BallPocket)
            .map(|(b, pocket, t)| (self.shot.tracks[b].id.clone(), pocket.to_string(), t))
            .collect()
    }

    /// Every ball's final state, as in the result document without reading it whole:
    /// (id, pos, vel, spin, motion).
    #[allow(clippy::type_complexity)]
    fn final_states(&self) -> Vec<(String, [f64; 3], [f64; 3], [f64; 3], &'static str)> {
        let xyz = |v: snooker_engine::Vec3| [v.x, v.y, v.z];
        self.shot
            .tracks
            .iter()
            .zip(self.shot.final_states())
            .map(|(t, s)| {
                (
                    t.id.clone(),
                    xyz(s.pos),
                    xyz(s.vel),
                    xyz(s.spin),
                    s.motion.name(),
                )
            })
            .collect()
    }

    /// Simulated duration, s.
    #[getter]
    fn duration(&self) -> f64 {
        self.shot.duration
    }

    /// Every ball's position (m) at each of `times` (s), from the exact trajectory: native
    /// f64 bytes of shape (times, balls, 3). Times outside [0, duration] are refused.
    fn positions<'py>(&self, py: Python<'py>, times: Vec<f64>) -> PyResult<Bound<'py, PyBytes>> {
        if let Some(t) = times
            .iter()
            .find(|t| !(t.is_finite() && **t >= 0.0 && **t <= self.shot.duration))
        {
            return Err(PyValueError::new_err(format!(
                "times: {t} s lies outside the shot, [0, {}] s",
                self.shot.duration
            )));
        }
        let p = &self.shot.params;
        let mut out = Vec::with_capacity(times.len() * self.shot.tracks.len() * 3 * 8);
        for &t in &times {
            for track in &self.shot.tracks {
                let s = track.state_at(t, p);
                for v in [s.pos.x, s.pos.y, s.pos.z] {
                    out.extend_from_slice(&v.to_ne_bytes());
                }
            }
        }
        Ok(PyBytes::new(py, &out))
    }
}

fn sim_error(scene: &snooker_scene::Scene, e: SimError) -> PyErr {
    SimulationError::new_err(format!("{}: {e}", scene.name))
}

/// Simulates a scene (the GIL released meanwhile).
#[pyfunction]
fn simulate(py: Python<'_>, scene: &Scene) -> PyResult<Shot> {
    let sc = scene.0.clone();
    let shot = py.detach(|| snooker_engine::simulate(&sc.setup, &sc.options));
    match shot {
        Ok(shot) => Ok(Shot { scene: sc, shot }),
        Err(e) => Err(sim_error(&sc, e)),
    }
}

/// Simulates many scenes on `threads` threads (all cores if None), the GIL released: per
/// scene, its shot or the message of its failure, in input order.
#[pyfunction]
#[pyo3(signature = (scenes, threads=None))]
fn simulate_many(
    py: Python<'_>,
    scenes: Vec<Py<Scene>>,
    threads: Option<usize>,
) -> PyResult<Vec<Py<PyAny>>> {
    let arcs: Vec<Arc<snooker_scene::Scene>> = scenes.iter().map(|s| s.get().0.clone()).collect();
    let shots = py
        .detach(|| snooker_batch::simulate_many(&arcs, threads, || {}))
        .map_err(|e| PyValueError::new_err(format!("threads: {e}")))?;
    arcs.into_iter()
        .zip(shots)
        .map(|(scene, shot)| match shot {
            Ok(shot) => Ok(Py::new(py, Shot { scene, shot })?.into_any()),
            Err(e) => Ok(sim_error(&scene, e).into_value(py).into_any()),
        })
        .collect()
}

/// The Python argument a planning request's field comes from, for messages.
pub(crate) fn argument(field: RequestField) -> String {
    match field {
        RequestField::CueBall => "cue_ball".into(),
        RequestField::Pot => "pot".into(),
        RequestField::Pocket => "pocket".into(),
        RequestField::Target => "cue_to".into(),
        RequestField::Tolerance => "tolerance".into(),
        RequestField::Samples => "samples".into(),
        RequestField::Alternatives => "alternatives".into(),
        RequestField::Bounds(v) => format!("bounds['{}']", v.name()),
        RequestField::Noise(c) => format!("noise['{}']", c.name()),
        RequestField::Kinds => "kinds".into(),
        RequestField::PlantBalls => "plant_balls".into(),
    }
}

/// The kinds of pot named (`direct`, `double`, `plant`, `kiss`), each once, at least one.
fn shot_kinds(names: &[String]) -> PyResult<Vec<ShotKind>> {
    let mut kinds = Vec::new();
    for name in names {
        let k = ShotKind::from_name(name).ok_or_else(|| {
            PyValueError::new_err(format!(
                "kinds: unknown kind '{name}' (direct, double, plant, kiss)"
            ))
        })?;
        if !kinds.contains(&k) {
            kinds.push(k);
        }
    }
    if kinds.is_empty() {
        return Err(PyValueError::new_err("kinds: name at least one kind"));
    }
    Ok(kinds)
}

/// Plans a shot (thesis chapter 7; as `snooker plan`): the plan document as Python values.
/// `noise` maps `aim`, `elevation`, `speed`, `side`, `height` (rad, m/s, m; `offset` for both
/// side and height) to standard deviations changing the standard noise; `bounds` maps `speed`,
/// `elevation`, `side`, `height` to (low, high).
#[pyfunction]
#[pyo3(signature = (scene, pot, pocket, cue_to, tolerance=0.001, noise=None, bounds=None,
                    samples=256, alternatives=3, seed=1, cue_ball="cue", kinds=None))]
#[allow(clippy::too_many_arguments)]
fn plan<'py>(
    py: Python<'py>,
    scene: &Scene,
    pot: &str,
    pocket: &str,
    cue_to: [f64; 2],
    tolerance: f64,
    noise: Option<BTreeMap<String, f64>>,
    bounds: Option<BTreeMap<String, (f64, f64)>>,
    samples: usize,
    alternatives: usize,
    seed: u64,
    cue_ball: &str,
    kinds: Option<Vec<String>>,
) -> PyResult<Bound<'py, PyAny>> {
    let sc = scene.0.clone();
    let p = sc.setup.params;
    let bad = |e: PlanError| match e {
        PlanError::BadInput { field, reason } => {
            PyValueError::new_err(format!("{}: {reason}", argument(field)))
        }
        PlanError::CannotPot(why) => CannotPot::new_err(format!("{}: {why}", sc.name)),
    };
    let mut request = Request {
        cue_ball: cue_ball.into(),
        tolerance,
        samples,
        alternatives,
        seed,
        ..Request::new(pot, pocket, cue_to, &p)
    };
    request.noise = noise::from_dict(request.noise, noise.unwrap_or_default())?;
    if let Some(names) = kinds {
        request.kinds = shot_kinds(&names)?;
    }
    for (name, (lo, hi)) in bounds.unwrap_or_default() {
        let v = StrikeVariable::from_name(&name).ok_or_else(|| {
            PyValueError::new_err(format!(
                "bounds['{name}']: unknown variable (speed, elevation, side, height)"
            ))
        })?;
        request.bounds.set(v, Interval { lo, hi });
    }
    let cancel = snooker_planner::Cancel::new();
    let problem = snooker_planner::Problem::new(&sc, request)
        .map_err(&bad)?
        .with_cancel(cancel.clone());
    let plan = interrupt::run(py, &cancel, || {
        snooker_planner::plan_problem(&problem, &sc.name)
    })?
    .map_err(bad)?;
    to_python(py, &plan)
}

/// The report of one impact (as `snooker impact --json`), as JSON text: `cut` (ball-ball,
/// degrees) or `angle` (cushion, degrees) says which; `params` are NAME=VALUE overrides.
fn impact(
    py: Python<'_>,
    geometry: Geometry,
    speed: f64,
    topspin: f64,
    sidespin: f64,
    params: BTreeMap<String, f64>,
) -> PyResult<Bound<'_, PyAny>> {
    let bad = |e: String| PyValueError::new_err(e);
    let given: Vec<(String, f64)> = params.into_iter().collect();
    let params = snooker_scene::override_params(snooker_engine::Params::default(), &given)
        .map_err(|e| match &e {
            snooker_scene::OverrideError::Unknown { name } => bad(format!("params['{name}']: {e}")),
            snooker_scene::OverrideError::Invalid(p) => {
                bad(format!("params['{}']: {}", p.name, p.reason))
            }
        })?;
    let spec = ImpactSpec {
        geometry,
        speed,
        topspin,
        sidespin,
        params,
    };
    let report = impact_report(&spec, None).map_err(|e| bad(e.to_string()))?;
    to_python(py, &report.doc)
}

/// A cue ball moving along +x at `speed` (m/s) meets a resting object ball at `cut` degrees.
#[pyfunction]
#[pyo3(signature = (speed, cut=0.0, topspin=0.0, sidespin=0.0, params=BTreeMap::new()))]
fn impact_ball_ball(
    py: Python<'_>,
    speed: f64,
    cut: f64,
    topspin: f64,
    sidespin: f64,
    params: BTreeMap<String, f64>,
) -> PyResult<Bound<'_, PyAny>> {
    impact(
        py,
        Geometry::BallBall { cut },
        speed,
        topspin,
        sidespin,
        params,
    )
}

/// A ball meets a cushion at `speed` (m/s), `angle` degrees from the cushion line.
#[pyfunction]
#[pyo3(signature = (speed, angle=90.0, topspin=0.0, sidespin=0.0, params=BTreeMap::new()))]
fn impact_cushion(
    py: Python<'_>,
    speed: f64,
    angle: f64,
    topspin: f64,
    sidespin: f64,
    params: BTreeMap<String, f64>,
) -> PyResult<Bound<'_, PyAny>> {
    impact(
        py,
        Geometry::Cushion { angle },
        speed,
        topspin,
        sidespin,
        params,
    )
}

/// The extension module.
#[pymodule]
fn _snooker(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Scene>()?;
    m.add("MAX_THREADS", snooker_batch::run::MAX_THREADS)?;
    // The standard noise by component, for the `"standard*K"` spelling of `noise`.
    let standard = pyo3::types::PyDict::new(m.py());
    for c in snooker_planner::NoiseComponent::ALL {
        standard.set_item(c.name(), snooker_planner::Noise::STANDARD.get(c))?;
    }
    m.add("STANDARD_NOISE", standard)?;
    m.add_class::<Shot>()?;
    m.add_class::<rules::Frame>()?;
    m.add_class::<rules::Verdict>()?;
    m.add_function(wrap_pyfunction!(load, m)?)?;
    m.add_function(wrap_pyfunction!(parse_toml, m)?)?;
    m.add_function(wrap_pyfunction!(parse_json, m)?)?;
    m.add_function(wrap_pyfunction!(parse_dict, m)?)?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(simulate_many, m)?)?;
    m.add_function(wrap_pyfunction!(plan, m)?)?;
    m.add_function(wrap_pyfunction!(play::play, m)?)?;
    m.add_function(wrap_pyfunction!(play::choose, m)?)?;
    m.add_function(wrap_pyfunction!(impact_ball_ball, m)?)?;
    m.add_function(wrap_pyfunction!(impact_cushion, m)?)?;
    m.add("SimulationError", m.py().get_type::<SimulationError>())?;
    m.add("CannotPot", m.py().get_type::<CannotPot>())?;
    Ok(())
}
