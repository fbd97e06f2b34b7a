//! `snooker referee`: a frame's strike simulated by the engine and judged by the rules of
//! snooker (formats.md, "Frame" and "Referee result"); the referee's JSON, the next frame,
//! and a recording of the strokes. Several frames are played in turn, each the frame the
//! stroke before left (but for the player's choices): one recording of the whole sequence.

use super::{bad_input, failed};
use crate::{output, record};
use snooker_engine::Shot;
use snooker_rules::file::FrameFile;
use snooker_rules::{Next, Verdict};
use snooker_scene::{SceneError, result};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Arguments of `snooker referee`.
#[derive(clap::Args)]
pub struct Args {
    /// Frame file (a scene file with a `[frame]` table and its `[cue]` strike); with several,
    /// each is played after the one before and must be the frame that stroke left but for the
    /// nomination (or a free ball declined) and the cue ball placed in hand, or after a foul
    /// that frame with the offender asked to play again, or the frame before the foul put back
    /// (a miss) with its points scored (the outputs are the last stroke's).
    #[arg(required = true, value_name = "FRAME.toml")]
    pub frames: Vec<PathBuf>,
    /// Write the referee's result (formats.md) as JSON to this file, or to standard output
    /// with `-`.
    #[arg(long, value_name = "OUT")]
    pub json: Option<String>,
    /// Write the frame after the stroke (no `[cue]`); nothing when the frame is over.
    #[arg(long, value_name = "NEXT.toml")]
    pub frame_out: Option<PathBuf>,
    /// Print nothing but errors (and the JSON if it goes to standard output).
    #[arg(long, short)]
    pub quiet: bool,
    /// Write a Rerun recording of the strokes on one timeline, the score and the ball on shown
    /// as the frame goes (see docs/rules.md).
    #[arg(long, value_name = "OUT.rrd")]
    pub record: Option<PathBuf>,
    /// Sample rate of the recording, Hz (every event instant is sampled as well).
    #[arg(long, value_name = "HZ", default_value_t = record::DEFAULT_RATE, requires = "record")]
    pub record_rate: f64,
}

/// One stroke played: its file, the shot and the verdict.
struct Played {
    file: FrameFile,
    shot: Shot,
    verdict: Verdict,
}

/// One line saying what a stroke was and what follows.
fn summary(n: usize, p: &Played) -> String {
    let s = p.file.frame.state();
    let v = &p.verdict;
    let mut on = s.on.to_string();
    if let Some(c) = s.nominated {
        on = format!("{on} ({}{c})", if s.free_ball { "free ball " } else { "" });
    }
    let mut text = format!(
        "stroke {n} ({}): player {} on {on}: ",
        p.file.file, s.to_play
    );
    match &v.foul {
        None => text += "legal",
        Some(f) => {
            text += &format!(
                "foul, {} ({} points to player {})",
                f.reason,
                f.points,
                1 - s.to_play
            )
        }
    }
    if let Some(hit) = &v.first_hit {
        text += &format!("; first hit {hit}");
    }
    if !v.potted.is_empty() {
        text += &format!("; potted {}", v.potted.join(", "));
    }
    if v.points > 0 {
        text += &format!(
            "; {} point{}",
            v.points,
            if v.points == 1 { "" } else { "s" }
        );
    }
    for (id, r) in &v.respotted {
        text += &format!("; {id} respotted at ({:.4}, {:.4})", r.pos.x, r.pos.y);
    }
    text += &format!("; scores {}-{}", v.scores[0], v.scores[1]);
    match (&v.next, v.winner) {
        (Some(n), _) => {
            text += &format!("; next: player {} on {}", n.to_play, n.on);
            if n.ball_in_hand {
                text += ", ball in hand";
            }
            if n.free_ball {
                text += ", free ball";
            }
        }
        (None, w) => text += &format!("; frame over, player {} wins", w.unwrap_or(0)),
    }
    text
}

/// Runs the command.
pub fn run(args: Args) -> ExitCode {
    let mut files = Vec::new();
    for path in &args.frames {
        match snooker_rules::load(path) {
            Ok(f) if f.strike.is_none() => {
                let e = SceneError::new(
                    &f.file,
                    "cue",
                    "a frame to referee needs its [cue] strike (on the cue ball)",
                );
                return bad_input(e);
            }
            Ok(f) => files.push(f),
            Err(e) => return bad_input(e),
        }
    }
    let json = args.json.as_deref();
    let outputs = [
        ("--json", json.filter(|o| *o != "-").map(PathBuf::from)),
        ("--frame-out", args.frame_out.clone()),
        ("--record", args.record.clone()),
    ];
    let inputs: Vec<&Path> = args.frames.iter().map(PathBuf::as_path).collect();
    if let Err(e) = output::check_outputs(&outputs, &inputs) {
        return bad_input(e);
    }
    let opts = record::RecordOptions {
        rate: args.record_rate,
        ..Default::default()
    };
    if args.record.is_some()
        && let Err(e) = opts.validate()
    {
        return bad_input(format!("--record-rate {}: {e}", opts.rate));
    }

    // Every stroke played and checked before anything is written.
    let mut played: Vec<Played> = Vec::new();
    for file in files {
        if let Some(prev) = played.last() {
            match prev.file.frame.next(&prev.verdict) {
                Next::Over { .. } => {
                    return bad_input(format!(
                        "{}: the frame ended with the stroke of {}",
                        file.file, prev.file.file
                    ));
                }
                Next::Play(expected) => {
                    // After a foul the offender may be asked to play again from the position
                    // left or, after a miss, put back (WPBSA Section 3 Rules 3(b), 13, 14):
                    // those frames follow as well.
                    let before = &prev.file.frame;
                    let again = [
                        before.play_again(&prev.verdict),
                        before.put_back(&prev.verdict),
                    ];
                    let candidates: Vec<&snooker_rules::Frame> = std::iter::once(&*expected)
                        .chain(again.iter().flatten())
                        .collect();
                    // The message is the one against the frame meant: the one with the same
                    // player to play (the offender's play-again, a put back), else the frame
                    // the stroke left.
                    let to_play = file.frame.state().to_play;
                    let meant = candidates
                        .iter()
                        .find(|c| c.state().to_play == to_play)
                        .unwrap_or(&candidates[0]);
                    if !candidates.iter().any(|c| file.frame.follows(c).is_ok())
                        && let Err(e) = file.frame.follows(meant)
                    {
                        let mut e = file.locate(&e);
                        e.reason = format!("{} ({})", e.reason, prev.file.file);
                        return bad_input(e);
                    }
                }
            }
        }
        let shot = match snooker_engine::simulate(&file.scene.setup, &file.scene.options) {
            Ok(s) => s,
            Err(e) => return failed(format!("{}: {e}", file.file)),
        };
        let verdict = match file.frame.judge(&shot) {
            Ok(v) => v,
            Err(e) => return failed(format!("{}: {e}", file.file)),
        };
        played.push(Played {
            file,
            shot,
            verdict,
        });
    }
    let Some(last) = played.last() else {
        return bad_input("no frame given (see --help)");
    };
    let json_to_stdout = json == Some("-");
    if !args.quiet {
        for (n, p) in played.iter().enumerate() {
            let line = summary(n + 1, p);
            if json_to_stdout {
                eprintln!("{line}");
            } else {
                outln!("{line}");
            }
        }
    }

    // Outputs, made whole before any is written.
    let doc = json.map(|_| {
        let shot = result::result_record(&last.file.scene, &last.shot);
        serde_json::to_string_pretty(&last.verdict.report(Some(shot)))
            .expect("JSON of finite numbers")
    });
    let next_frame = match last.file.frame.next(&last.verdict) {
        Next::Play(f) => Some(f.to_toml(None)),
        Next::Over { .. } => None,
    };
    let recording = match &args.record {
        None => None,
        Some(out) => {
            let strokes: Vec<record::frame::RecordedStroke> = played
                .iter()
                .map(|p| record::frame::RecordedStroke {
                    frame: &p.file.frame,
                    shot: &p.shot,
                    verdict: &p.verdict,
                })
                .collect();
            match record::frame::encode_strokes(&strokes, &opts) {
                Ok(bytes) => Some((out, bytes)),
                Err(e @ (record::RecordError::Rate(_) | record::RecordError::TooLarge(_))) => {
                    return bad_input(format!("--record {}: {e}", out.display()));
                }
                Err(e) => return failed(format!("--record {}: {e}", out.display())),
            }
        }
    };

    // Every file staged whole before any is put in place (output::Outputs).
    let mut files = output::Outputs::default();
    files.add_json(json, doc.as_ref());
    if let (Some(out), Some(text)) = (&args.frame_out, &next_frame) {
        files.add("--frame-out", out, text.as_bytes());
    }
    if let Some((out, bytes)) = &recording {
        files.add("--record", out, bytes);
    }
    if let Err(e) = files.commit() {
        return bad_input(e);
    }
    match (json, doc) {
        (Some("-"), Some(text)) => {
            let mut stdout = std::io::stdout().lock();
            if writeln!(stdout, "{text}").is_err() {
                return ExitCode::from(super::FAILED);
            }
        }
        (Some(out), Some(_)) if !args.quiet => outln!("result written to {out}"),
        _ => {}
    }
    if let Some(out) = &args.frame_out {
        match next_frame {
            Some(_) if !args.quiet && !json_to_stdout => {
                outln!("next frame written to {}", out.display());
            }
            Some(_) => {}
            None => eprintln!(
                "the frame is over: --frame-out {} not written",
                out.display()
            ),
        }
    }
    if let Some((out, _)) = recording {
        super::say_recording_written(out, args.quiet, json_to_stdout);
    }
    ExitCode::SUCCESS
}
