//! `snooker play`: the player plays a visit or a frame from a frame file under execution noise
//! (formats.md, "Play log"): a line per stroke on the terminal, the play log, a summary as
//! JSON, and the whole sequence as one Rerun recording with the planned target and the path
//! intended beside the one played.

use super::{bad_input, failed, spec};
use crate::{output, record};
use rerun::{Color, LineStrips3D, Points3D};
use snooker_planner::Noise;
use snooker_player::game::{DEFAULT_EFFORT, DEFAULT_MAX_STROKES};
use snooker_player::{Agent, End, Game, Greedy, PlayOptions, Player, StrokeRecord, Until, play};
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

/// Arguments of `snooker play`.
#[derive(clap::Args)]
pub struct Args {
    /// Frame file (a scene file with a `[frame]` table; its `[cue]`, if any, is ignored).
    #[arg(value_name = "FRAME.toml")]
    pub frame: PathBuf,
    /// Play until the player at the table misses or fouls: one visit (the default).
    #[arg(long, conflicts_with = "frame_mode")]
    pub visit: bool,
    /// Play until the frame ends, both sides (a stroke cap, --max-strokes, ends a frame that
    /// cannot).
    #[arg(long = "frame", id = "frame_mode")]
    pub frame_mode: bool,
    /// Execution noise added to every stroke: "standard" (the default: the computational pool
    /// tournaments' noise, aim 0.125 deg, elevation 0.1 deg, speed 0.075 m/s, side and height
    /// 0.5 mm), "standard*K", "0", or NAME=VALUE items (aim, elevation in rad, speed in m/s,
    /// side, height in m), e.g. "0,aim=0.002".
    #[arg(long, value_name = "SPEC")]
    pub noise: Option<String>,
    /// Seed of every random draw (the noise played, the noise sampled while deciding).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// The search's budget per stroke, in simulated shots.
    #[arg(long, value_name = "N", default_value_t = DEFAULT_EFFORT)]
    pub effort: u64,
    /// Most strokes played.
    #[arg(long, value_name = "N", default_value_t = DEFAULT_MAX_STROKES)]
    pub max_strokes: usize,
    /// Who plays player 1's strokes in a frame: the player, or the greedy baseline (the
    /// likeliest pot, no position, no safety).
    #[arg(long, value_name = "AGENT", default_value = "player")]
    pub opponent: String,
    /// Threads to simulate on, 1 to 1024 (default: every core); the log does not depend on it
    /// (but for each line's decision_time, the wall clock).
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
    /// Write the play log (formats.md, "Play log"): one JSON line per stroke.
    #[arg(long, value_name = "OUT.jsonl")]
    pub log: Option<PathBuf>,
    /// Write a Rerun recording of the strokes on one timeline, with the planned target and
    /// the path intended beside the one played; it opens at the end, with every stroke's
    /// cue-ball path.
    #[arg(long, value_name = "OUT.rrd")]
    pub record: Option<PathBuf>,
    /// Write a summary as JSON to this file, or to standard output with `-`.
    #[arg(long, value_name = "SUMMARY.json")]
    pub json: Option<String>,
    /// Print nothing but errors (and the JSON if it goes to standard output).
    #[arg(long, short)]
    pub quiet: bool,
}

/// The summary document of `--json`.
#[derive(serde::Serialize)]
struct Summary<'a> {
    frame: &'a str,
    mode: &'static str,
    noise: Noise,
    seed: u64,
    effort: u64,
    strokes: usize,
    end: &'static str,
    winner: Option<u8>,
    scores: [u32; 2],
    /// Points scored by each player's strokes (a visit: the break is player's).
    points: [u32; 2],
    /// Pots attempted (strokes planned as pots) and potted legally, by player.
    pots_attempted: [usize; 2],
    pots_made: [usize; 2],
    fouls: [usize; 2],
    /// Decision times, s.
    decision_time_median: f64,
    decision_time_max: f64,
    shots_simulated: u64,
}

/// Colours of the overlays: the planned target, the path intended.
const TARGET_COLOR: [u8; 3] = [255, 64, 255];
const INTENDED_COLOR: [u8; 3] = [150, 150, 150];

fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

fn summary<'a>(file: &'a str, args: &Args, opts: &PlayOptions, game: &Game) -> Summary<'a> {
    let mut points = [0; 2];
    let (mut attempted, mut made, mut fouls) = ([0; 2], [0; 2], [0; 2]);
    for s in &game.strokes {
        let p = s.player as usize;
        points[p] += s.verdict.points;
        if s.decision.plan.kind != snooker_player::PlanKind::Safety {
            attempted[p] += 1;
            if s.verdict.legal() && s.verdict.potted.contains(&s.decision.plan.pot) {
                made[p] += 1;
            }
        }
        if !s.verdict.legal() {
            fouls[p] += 1;
        }
    }
    let scores = game.strokes.last().map_or([0, 0], |s| s.verdict.scores);
    let times: Vec<f64> = game.strokes.iter().map(|s| s.decision_time).collect();
    Summary {
        frame: file,
        mode: if args.frame_mode { "frame" } else { "visit" },
        noise: opts.noise,
        seed: opts.seed,
        effort: opts.effort,
        strokes: game.strokes.len(),
        end: match game.end {
            End::VisitOver => "visit_over",
            End::FrameOver { .. } => "frame_over",
            End::StrokeCap => "stroke_cap",
        },
        winner: match game.end {
            End::FrameOver { winner, .. } => Some(winner),
            _ => None,
        },
        scores,
        points,
        pots_attempted: attempted,
        pots_made: made,
        fouls,
        decision_time_median: median(times.clone()),
        decision_time_max: times.iter().copied().fold(0.0, f64::max),
        shots_simulated: game.strokes.iter().map(|s| s.decision.shots).sum(),
    }
}

/// One line for the terminal.
fn line(s: &StrokeRecord) -> String {
    let p = &s.decision.plan;
    let what = match p.kind {
        snooker_player::PlanKind::Safety if p.via.is_empty() => format!("safety off {}", p.ball),
        // An escape from a snooker: the cushions the cue ball meets first.
        snooker_player::PlanKind::Safety => {
            format!("safety off {} via {}", p.ball, p.via.join(", "))
        }
        k => format!("{} {} in {}", k.name(), p.pot, p.pocket),
    };
    let v = &s.verdict;
    let result = match &v.foul {
        Some(f) => format!("foul, {} ({} away)", f.reason, f.points),
        None if v.points > 0 => format!("potted {} (+{})", v.potted.join(", "), v.points),
        None => "no pot".to_string(),
    };
    format!(
        "stroke {} ({}, player {}): {what}, pot chance {:.0} %: {result}; scores {}-{} \
         ({:.2} s, {} shots)",
        s.number,
        s.agent,
        s.player,
        100.0 * p.pot_probability,
        v.scores[0],
        v.scores[1],
        s.decision_time,
        s.decision.shots
    )
}

/// The recording: the strokes, and for each its planned target and the path intended.
fn recording(game: &Game) -> Result<Vec<u8>, record::RecordError> {
    let strokes: Vec<record::frame::RecordedStroke> = game
        .strokes
        .iter()
        .map(|s| record::frame::RecordedStroke {
            frame: &s.frame,
            shot: &s.shot,
            verdict: &s.verdict,
        })
        .collect();
    let rgb = |c: [u8; 3]| Color::from_rgb(c[0], c[1], c[2]);
    // A break is looked at from its end: the table it left, the score, and the cue ball's
    // way through every stroke.
    let opts = record::RecordOptions {
        open_at: record::OpenAt::End,
        ..Default::default()
    };
    record::frame::encode_strokes_with(&strokes, &opts, |rec, starts| {
        for (s, &t0) in game.strokes.iter().zip(starts) {
            let r = s.frame.params().ball_radius;
            rec.set_duration_secs(record::TIMELINE, t0);
            let to = s.decision.plan.cue_to;
            rec.log(
                "plan/target",
                &Points3D::new([[to[0] as f32, to[1] as f32, r as f32]])
                    .with_colors([rgb(TARGET_COLOR)])
                    .with_radii([rerun::Radius::new_scene_units(0.4 * r as f32)]),
            )
            .map_err(record::rerun_err)?;
            // The path the cue ball would have taken had the strike been played as meant,
            // drawn as the one played is.
            let meant = &s.decision.strike;
            let path: Vec<[f32; 3]> = match (s.frame.cue_index(), s.frame.setup(meant).ok()) {
                (Some(cue), Some(setup)) => snooker_engine::simulate(&setup, s.frame.options())
                    .map_or_else(|_| Vec::new(), |shot| cue_way(&shot, cue, meant.speed)),
                _ => Vec::new(),
            };
            rec.log(
                "plan/intended",
                &LineStrips3D::new([path])
                    .with_colors([rgb(INTENDED_COLOR)])
                    .with_radii([rerun::Radius::new_ui_points(1.0)]),
            )
            .map_err(record::rerun_err)?;
        }
        // The cue ball's paths as played, one strip per stroke, shown once the last stroke
        // has ended (points where its way turns, and every 5 cm between).
        if let Some((last, &t_last)) = game.strokes.last().zip(starts.last()) {
            let strips: Vec<Vec<[f32; 3]>> = game
                .strokes
                .iter()
                .map(|s| {
                    s.frame
                        .cue_index()
                        .map_or_else(Vec::new, |cue| cue_way(&s.shot, cue, s.executed.speed))
                })
                .collect();
            rec.set_duration_secs(record::TIMELINE, t_last + last.shot.duration);
            rec.log(
                "plan/played",
                &LineStrips3D::new(strips)
                    .with_colors([rgb(PLAYED_COLOR)])
                    .with_radii([rerun::Radius::new_ui_points(1.5)]),
            )
            .map_err(record::rerun_err)?;
        }
        Ok(())
    })
}

/// Colour of the cue ball's paths as played, in a recording.
const PLAYED_COLOR: [u8; 3] = [240, 240, 240];

/// The path of ball `cue` in `shot`, struck at cue speed `speed`, at
/// [`record::sample::way_times`], while it is on the table.
fn cue_way(shot: &snooker_engine::Shot, cue: usize, speed: f64) -> Vec<[f32; 3]> {
    let track = &shot.tracks[cue];
    record::sample::way_times(shot, cue, speed)
        .iter()
        .map(|&t| track.state_at(t, &shot.params))
        .filter(|st| st.motion.in_play())
        .map(|st| [st.pos.x as f32, st.pos.y as f32, st.pos.z as f32])
        .collect()
}

/// Runs the command.
pub fn run(args: Args) -> ExitCode {
    let file = match snooker_rules::file::load_position(&args.frame) {
        Ok(f) => f,
        Err(e) => return bad_input(e),
    };
    let noise = match spec::noise(
        "--noise",
        args.noise.as_deref().unwrap_or(""),
        Noise::STANDARD,
    ) {
        Ok(n) => n,
        Err(e) => return bad_input(e),
    };
    let opponent: &dyn Agent = match args.opponent.as_str() {
        "player" => &Player,
        "greedy" => &Greedy,
        other => {
            return bad_input(format!(
                "--opponent {other}: unknown agent (player, greedy)"
            ));
        }
    };
    let json = args.json.as_deref();
    let outputs = [
        ("--json", json.filter(|o| *o != "-").map(PathBuf::from)),
        ("--log", args.log.clone()),
        ("--record", args.record.clone()),
    ];
    if let Err(e) = output::check_outputs(&outputs, &[&args.frame]) {
        return bad_input(e);
    }
    let opts = PlayOptions {
        noise,
        seed: args.seed,
        effort: args.effort,
        until: if args.frame_mode {
            Until::Frame
        } else {
            Until::Visit
        },
        max_strokes: args.max_strokes,
        watch: Default::default(),
    };
    if let Err(e) = opts.check() {
        let flag = match e.key.as_str() {
            "effort" => "--effort",
            "max_strokes" => "--max-strokes",
            _ => "--noise",
        };
        return bad_input(format!("{flag}: {}", e.reason));
    }
    // The batch's bound: rayon starts every thread asked for (100,000 took minutes).
    if let Some(Err(e)) = args.threads.map(snooker_batch::run::check_threads) {
        return bad_input(format!("--threads {}: {}", e.threads, e.reason));
    }
    let pool = match rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads.unwrap_or(0))
        .build()
    {
        Ok(p) => p,
        Err(e) => return bad_input(format!("--threads: {e}")),
    };
    let to_stdout = json == Some("-");
    let quiet = args.quiet;
    // Player 0 is the player; player 1 the opponent chosen.
    let agents: [&dyn Agent; 2] = [&Player, opponent];
    let game = pool.install(|| {
        play(&file.frame, agents, &opts, |s| {
            if !quiet {
                let l = line(s);
                if to_stdout {
                    eprintln!("{l}");
                } else {
                    outln!("{l}");
                }
            }
        })
    });
    let game = match game {
        Ok(g) => g,
        Err(e) => return failed(format!("{}: {e}", file.file)),
    };
    let sum = summary(&file.file, &args, &opts, &game);
    if !quiet {
        let l = format!(
            "{}: {} strokes, points {}-{}, scores {}-{}; decision time median {:.2} s",
            sum.end,
            sum.strokes,
            sum.points[0],
            sum.points[1],
            sum.scores[0],
            sum.scores[1],
            sum.decision_time_median
        );
        if to_stdout {
            eprintln!("{l}");
        } else {
            outln!("{l}");
        }
    }
    // Outputs, made whole before any is written.
    let log = args.log.as_ref().map(|_| {
        let mut text = String::new();
        for s in &game.strokes {
            text.push_str(&s.log_json());
            text.push('\n');
        }
        text
    });
    let doc = json.map(|_| serde_json::to_string_pretty(&sum).expect("JSON of finite numbers"));
    let rrd = match &args.record {
        None => None,
        Some(out) => match recording(&game) {
            Ok(bytes) => Some((out, bytes)),
            Err(e @ record::RecordError::TooLarge(_)) => {
                return bad_input(format!("--record {}: {e}", out.display()));
            }
            Err(e) => return failed(format!("--record {}: {e}", out.display())),
        },
    };
    // Every file staged whole before any is put in place (output::Outputs).
    let mut files = output::Outputs::default();
    if let (Some(out), Some(text)) = (&args.log, &log) {
        files.add("--log", out, text.as_bytes());
    }
    files.add_json(json, doc.as_ref());
    if let Some((out, bytes)) = &rrd {
        files.add("--record", out, bytes);
    }
    if let Err(e) = files.commit() {
        return bad_input(e);
    }
    if let (Some("-"), Some(text)) = (json, doc) {
        let mut stdout = std::io::stdout().lock();
        if writeln!(stdout, "{text}").is_err() {
            return ExitCode::from(super::FAILED);
        }
    }
    ExitCode::SUCCESS
}
