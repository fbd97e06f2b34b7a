//! `snooker plan`: the strike that pots a ball and leaves the cue ball nearest a target
//! (thesis chapter 7), with its robustness to execution noise and genuinely different
//! alternatives; the scene with that strike, the plan as JSON, and a recording.

use super::{bad_input, failed, spec};
use crate::{output, record};
use anyhow::Context;
use indicatif::{ProgressBar, ProgressStyle};
use snooker_engine::Vec3;
use snooker_planner::{
    self as planner, Bounds, Interval, Noise, Plan, PlanError, Problem, Request, RequestField,
    ShotKind, StrikeVariable,
};
use snooker_scene as scene;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

/// Arguments of `snooker plan`.
#[derive(clap::Args)]
pub struct Args {
    /// Scene file: the balls where they lie (its `[cue]` is ignored).
    pub scene: PathBuf,
    /// The ball to pot (its id).
    #[arg(long)]
    pub pot: String,
    /// The pocket (top-left, top-right, middle-left, middle-right, baulk-left, baulk-right).
    #[arg(long)]
    pub pocket: String,
    /// Where the cue ball should stop, "X,Y" in metres (table frame).
    #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
    pub cue_to: String,
    /// Distance to the target that counts as reached, m.
    #[arg(long, default_value_t = 0.001)]
    pub tolerance: f64,
    /// Execution noise (standard deviations): "standard" (the default: the computational pool
    /// tournaments' noise, aim 0.125 deg, elevation 0.1 deg, speed 0.075 m/s, side and height
    /// 0.5 mm), "standard*K", "0", or NAME=VALUE items changing it (aim, elevation in rad,
    /// speed in m/s, side, height in m), e.g. "0,aim=0.002". Before, speed was a fraction of
    /// the cue speed and offset one value for both offsets: offset=M is still side=M,height=M.
    #[arg(long, value_name = "SPEC")]
    pub noise: Option<String>,
    /// Monte Carlo samples per shot for its pot probability.
    #[arg(long, default_value_t = 256)]
    pub samples: usize,
    /// Most alternative shots (each on another route of the cue ball).
    #[arg(long, value_name = "N", default_value_t = 3)]
    pub alternatives: usize,
    /// Search bounds, e.g. "speed=0.3..6,elevation=0..0,side=-0.01..0.01,height=-0.01..0.01"
    /// (m/s, rad, m, m); unnamed variables keep their defaults.
    #[arg(long, value_name = "SPEC")]
    pub bounds: Option<String>,
    /// The ball struck.
    #[arg(long, default_value = "cue")]
    pub cue_ball: String,
    /// The kinds of pot tried, comma-separated: direct (cue ball, object ball, pocket), double
    /// (the object ball off one or two cushions), plant (through another ball), kiss (the
    /// object ball glancing off another ball). Direct pots are tried first, the others when
    /// those do not reach the target.
    #[arg(long, value_name = "KINDS", default_value = "direct,double,plant,kiss")]
    pub kinds: String,
    /// The balls a plant may strike first, comma-separated ids (e.g. "red1,red2": by the
    /// rules a plant's first ball must be a ball on); every other ball when not given.
    #[arg(long, value_name = "IDS")]
    pub plant_balls: Option<String>,
    /// Write the plan as JSON to this file, or to standard output with `-`.
    #[arg(long, value_name = "OUT")]
    pub json: Option<String>,
    /// Write the scene with the planned strike as its `[cue]` (replays with `snooker
    /// simulate`).
    #[arg(long, value_name = "OUT.toml")]
    pub scene_out: Option<PathBuf>,
    /// Write a Rerun recording of the planned shot, the target, the pocket and the
    /// alternatives' cue-ball paths.
    #[arg(long, value_name = "OUT.rrd")]
    pub record: Option<PathBuf>,
    /// Seed of the noise samples.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Print nothing but errors (and the JSON if it goes to standard output).
    #[arg(long, short)]
    pub quiet: bool,
}

/// Colours of the overlays: the target, the pocket, the alternatives' paths.
const TARGET_COLOR: [u8; 3] = [255, 64, 255];
const POCKET_COLOR: [u8; 3] = [255, 220, 0];
const ALTERNATIVE_COLOR: [u8; 3] = [150, 150, 150];

fn parse_target(s: &str) -> Result<[f64; 2], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    let nums: Vec<f64> = parts
        .iter()
        .filter_map(|p| p.parse::<f64>().ok())
        .filter(|v| v.is_finite())
        .collect();
    match (parts.len(), nums.as_slice()) {
        (2, [x, y]) => Ok([*x, *y]),
        _ => Err(format!(
            "expected two finite numbers \"X,Y\" in metres, got \"{s}\""
        )),
    }
}

/// The flag (and the part of its spec) a request field comes from: the planner names its
/// own fields, the command names what its user typed.
fn flag(field: RequestField) -> String {
    match field {
        RequestField::CueBall => "--cue-ball".into(),
        RequestField::Pot => "--pot".into(),
        RequestField::Pocket => "--pocket".into(),
        RequestField::Target => "--cue-to".into(),
        RequestField::Tolerance => "--tolerance".into(),
        RequestField::Samples => "--samples".into(),
        RequestField::Alternatives => "--alternatives".into(),
        RequestField::Bounds(v) => format!("--bounds {}", v.name()),
        RequestField::Noise(c) => format!("--noise {}", c.name()),
        RequestField::Kinds => "--kinds".into(),
        RequestField::PlantBalls => "--plant-balls".into(),
    }
}

/// A planner error as the command says it: the field named by its flag.
fn plan_error(e: &PlanError) -> String {
    match e {
        PlanError::BadInput { field, reason } => format!("{}: {reason}", flag(*field)),
        PlanError::CannotPot(why) => why.clone(),
    }
}

/// `bounds` with the intervals of `spec` ("speed=0.3..6,elevation=0..0,side=-0.01..0.01,
/// height=..."); the planner checks them against the engine's limits.
fn parse_bounds(spec: &str, mut bounds: Bounds) -> Result<Bounds, String> {
    let mut given = Vec::new();
    for part in spec.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        let syntax = || format!("--bounds {part}: expected NAME=LO..HI");
        let (name, range) = part.split_once('=').ok_or_else(syntax)?;
        let (lo, hi) = range.split_once("..").ok_or_else(syntax)?;
        let var = StrikeVariable::from_name(name.trim()).ok_or_else(|| {
            format!(
                "--bounds {part}: unknown variable `{}` (speed, elevation, side, height)",
                name.trim()
            )
        })?;
        // A variable given twice kept its last interval silently: a typo, refused.
        if given.contains(&var) {
            return Err(format!("--bounds {spec}: `{}` is given twice", name.trim()));
        }
        given.push(var);
        let num = |s: &str| {
            s.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("--bounds {part}: `{s}` is not a finite number"))
        };
        bounds.set(
            var,
            Interval {
                lo: num(lo)?,
                hi: num(hi)?,
            },
        );
    }
    Ok(bounds)
}

/// The kinds of pot named in `spec` ("direct,double,plant,kiss").
fn parse_kinds(spec: &str) -> Result<Vec<ShotKind>, String> {
    let mut kinds = Vec::new();
    for name in spec.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        let k = ShotKind::from_name(name).ok_or_else(|| {
            format!("--kinds {spec}: unknown kind `{name}` (direct, double, plant, kiss)")
        })?;
        if !kinds.contains(&k) {
            kinds.push(k);
        }
    }
    if kinds.is_empty() {
        return Err(format!("--kinds {spec}: name at least one kind"));
    }
    Ok(kinds)
}

/// The ball ids named in `spec` ("red1,red2"), each once; the planner checks that they exist.
fn parse_plant_balls(spec: &str) -> Result<Vec<String>, String> {
    let mut ids: Vec<String> = Vec::new();
    for id in spec.split(',').map(str::trim) {
        if id.is_empty() {
            return Err(format!("--plant-balls {spec}: an empty ball id"));
        }
        if ids.iter().any(|i| i == id) {
            return Err(format!("--plant-balls {spec}: `{id}` named twice"));
        }
        ids.push(id.to_string());
    }
    Ok(ids)
}

/// Runs the command.
pub fn run(args: Args) -> ExitCode {
    let file = args.scene.display().to_string();
    let text = match snooker_scene::read_text(&args.scene) {
        Ok(t) => t,
        Err(e) => return bad_input(format!("{file}: cannot read the scene file: {e}")),
    };
    let scene = match scene::parse(&text, &file) {
        Ok(s) => s,
        Err(e) => return bad_input(e),
    };
    let p = scene.setup.params;
    let target = match parse_target(&args.cue_to) {
        Ok(t) => t,
        Err(e) => return bad_input(format!("--cue-to: {e}")),
    };
    let noise = match spec::noise(
        "--noise",
        args.noise.as_deref().unwrap_or(""),
        Noise::STANDARD,
    ) {
        Ok(n) => n,
        Err(e) => return bad_input(e),
    };
    let bounds = match parse_bounds(
        args.bounds.as_deref().unwrap_or(""),
        Bounds::default_for(&p),
    ) {
        Ok(b) => b,
        Err(e) => return bad_input(e),
    };
    let kinds = match parse_kinds(&args.kinds) {
        Ok(k) => k,
        Err(e) => return bad_input(e),
    };
    let plant_balls = match args.plant_balls.as_deref().map(parse_plant_balls) {
        None => None,
        Some(Ok(ids)) => Some(ids),
        Some(Err(e)) => return bad_input(e),
    };
    let json = args.json.as_deref();
    let outputs = [
        ("--json", json.filter(|o| *o != "-").map(PathBuf::from)),
        ("--scene-out", args.scene_out.clone()),
        ("--record", args.record.clone()),
    ];
    if let Err(e) = output::check_outputs(&outputs, &[&args.scene]) {
        return bad_input(e);
    }
    let request = Request {
        cue_ball: args.cue_ball.clone(),
        tolerance: args.tolerance,
        bounds,
        noise,
        samples: args.samples,
        alternatives: args.alternatives,
        seed: args.seed,
        kinds,
        plant_balls,
        ..Request::new(&args.pot, &args.pocket, target, &p)
    };
    let problem = match Problem::new(&scene, request) {
        Ok(pr) => pr,
        Err(e) => return bad_input(plan_error(&e)),
    };
    let plan = match with_progress(&problem, &scene.name, args.quiet) {
        Ok(plan) => plan,
        Err(e @ PlanError::BadInput { .. }) => return bad_input(plan_error(&e)),
        Err(e @ PlanError::CannotPot(_)) => return failed(format!("{file}: {}", plan_error(&e))),
    };
    // The contract: the scene written replays the planned shot to the bit. Checked here.
    let out_text = match planner::scene_out::with_strike(&text, &plan.best.strike) {
        Ok(t) => t,
        Err(e) => return failed(format!("{file}: cannot write the scene again: {e}")),
    };
    let replay = match replay(&out_text, &file, &plan, problem.cue()) {
        Ok(r) => r,
        Err(e) => return failed(format!("internal error: {e:#}")),
    };
    if !args.quiet {
        let text = summary(&plan);
        if json == Some("-") {
            eprint!("{text}");
        } else {
            out!("{text}");
        }
    }
    let recording = match &args.record {
        None => None,
        Some(out) => match recording(&problem, &plan, &replay) {
            Ok(bytes) => Some((out, bytes)),
            Err(e) => return failed(format!("--record {}: {e:#}", out.display())),
        },
    };
    let text = json.map(|_| serde_json::to_string_pretty(&plan).expect("JSON of finite numbers"));
    // Every file staged whole before any is put in place (output::Outputs).
    let mut files = output::Outputs::default();
    files.add_json(json, text.as_ref());
    if let Some(out) = &args.scene_out {
        files.add("--scene-out", out, out_text.as_bytes());
    }
    if let Some((out, bytes)) = &recording {
        files.add("--record", out, bytes);
    }
    if let Err(e) = files.commit() {
        return bad_input(e);
    }
    if let (Some("-"), Some(text)) = (json, text) {
        outln!("{text}");
    }
    ExitCode::SUCCESS
}

/// Plans, with a spinner on standard error once the search takes more than a moment.
fn with_progress(problem: &Problem, name: &str, quiet: bool) -> Result<Plan, PlanError> {
    let done = AtomicBool::new(false);
    std::thread::scope(|s| {
        if !quiet {
            s.spawn(|| {
                std::thread::sleep(Duration::from_millis(300));
                if done.load(Ordering::Relaxed) {
                    return;
                }
                let bar = ProgressBar::new_spinner();
                if let Ok(style) =
                    ProgressStyle::with_template("{spinner} planning: {msg} ({elapsed})")
                {
                    bar.set_style(style);
                }
                while !done.load(Ordering::Relaxed) {
                    bar.set_message(format!("{} shots simulated", problem.shots()));
                    bar.tick();
                    std::thread::sleep(Duration::from_millis(100));
                }
                bar.finish_and_clear();
            });
        }
        let plan = planner::plan_problem(problem, name);
        done.store(true, Ordering::Relaxed);
        plan
    })
}

/// Simulates the scene written with the plan's strike, as `snooker simulate` does, and checks
/// that the cue ball ends where the planner saw it, to the bit.
fn replay(
    text: &str,
    file: &str,
    plan: &Plan,
    cue: usize,
) -> anyhow::Result<(scene::Scene, snooker_engine::Shot)> {
    let sc = scene::parse(text, file).context("the planned scene")?;
    let shot = snooker_engine::simulate(&sc.setup, &sc.options).context("the planned scene")?;
    let end = shot.final_states()[cue].pos;
    if [end.x.to_bits(), end.y.to_bits()] != plan.best.cue_final.map(f64::to_bits) {
        anyhow::bail!(
            "the planned shot does not replay: the cue ball ends at ({}, {}), the plan says ({}, {})",
            end.x,
            end.y,
            plan.best.cue_final[0],
            plan.best.cue_final[1]
        );
    }
    Ok((sc, shot))
}

/// A few lines for the terminal.
fn summary(plan: &Plan) -> String {
    let line = |tag: &str, s: &planner::PlannedShot| {
        let st = &s.strike;
        format!(
            "{tag:<6} speed {:.3} m/s, aim {:.5} rad, offset ({:+.1}, {:+.1}) mm, elevation {:.3} rad \
             -> cue ball at ({:.4}, {:.4}), {:.1} mm from the target; {}{}; {} via [{}]; pots \
             {:.0} % under noise, ends spread {:.0} mm\n",
            st.speed,
            st.aim,
            st.offset[0] * 1e3,
            st.offset[1] * 1e3,
            st.elevation,
            s.cue_final[0],
            s.cue_final[1],
            s.distance * 1e3,
            s.route.kind.name(),
            if s.route.via.is_empty() {
                String::new()
            } else {
                format!(" ({})", s.route.via.join(", "))
            },
            s.route.spin,
            s.route.cushions.join(", "),
            100.0 * s.robustness.pot_probability,
            s.robustness.cue_final_spread * 1e3,
        )
    };
    let mut out = format!(
        "plan: pot {} in {}, cue ball to ({}, {}): {} ({} shots simulated in {:.2} s)\n",
        plan.pot,
        plan.pocket,
        plan.target[0],
        plan.target[1],
        if plan.reached {
            format!("reached within {} mm", plan.tolerance * 1e3)
        } else {
            "not reached; the nearest pot found".to_string()
        },
        plan.shots_simulated,
        plan.wall_time
    );
    out.push_str(&line("best", &plan.best));
    for a in &plan.alternatives {
        out.push_str(&line("alt", a));
    }
    out
}

/// The planned shot's recording, with the target, the pocket's fall circle and the
/// alternatives' cue-ball paths over it.
fn recording(
    problem: &Problem,
    plan: &Plan,
    replay: &(scene::Scene, snooker_engine::Shot),
) -> anyhow::Result<Vec<u8>> {
    let (sc, shot) = replay;
    let r = problem.setup().params.ball_radius;
    let mut overlays = vec![record::Overlay {
        entity: vec!["plan".into(), "target".into()],
        points: vec![(0.0, problem.target()), (shot.duration, problem.target())],
        color: TARGET_COLOR,
        radius: r,
    }];
    let pocket = &problem.setup().table.pockets[problem.pocket()];
    overlays.push(record::Overlay {
        entity: vec!["plan".into(), "pocket".into()],
        points: (0..=48)
            .map(|k| {
                let a = k as f64 * std::f64::consts::TAU / 48.0;
                let at = pocket.centre + pocket.radius * Vec3::new(a.cos(), a.sin(), 0.0);
                (0.0, Vec3::new(at.x, at.y, r))
            })
            .collect(),
        color: POCKET_COLOR,
        radius: 0.002,
    });
    for (k, alt) in plan.alternatives.iter().enumerate() {
        let mut setup = problem.setup().clone();
        setup.balls[problem.cue()].strike(&alt.strike.cue(), &problem.setup().params)?;
        let alt_shot = snooker_engine::simulate(&setup, problem.options())?;
        let track = &alt_shot.tracks[problem.cue()];
        // Through every turn of its way, as `play --record` draws a path.
        let times = record::sample::way_times(&alt_shot, problem.cue(), alt.strike.speed);
        overlays.push(record::Overlay {
            entity: vec!["plan".into(), format!("alternative{}", k + 1)],
            points: times
                .into_iter()
                .map(|t| (t, track.state_at(t, &alt_shot.params)))
                .filter(|(_, st)| st.motion.in_play())
                .map(|(t, st)| (t, st.pos))
                .collect(),
            color: ALTERNATIVE_COLOR,
            radius: 0.25 * r,
        });
    }
    Ok(record::encode_with_overlays(
        sc,
        shot,
        &record::RecordOptions::default(),
        &overlays,
    )?)
}
