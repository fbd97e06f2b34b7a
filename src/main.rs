//! `snooker`: simulate snooker shots from scene files, resolve single impacts, cross-check
//! against rapier, and find and name discrepancies with measurements.

use clap::{Parser, Subcommand};
use snooker::cmd::{
    self, batch, discrepancy, impact, plan, play, referee, serve, simulate, synth, validate,
};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    version,
    about = "Event-driven snooker physics engine (SI units, table frame)"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Simulate a scene and print a summary (the built-in break-off when no scene is given).
    Simulate(simulate::Args),
    /// One impact of the thesis's frictional models (chapter 6): the state just after it and
    /// once the slip on the cloth has ended. Spins in units of V/R as in the thesis's figures.
    Impact(impact::Args),
    /// Cross-check the engine against rapier on the validation scenes (or the given ones) and
    /// print the report; exits with 1 when a verdict fails.
    Validate(validate::Args),
    /// Make measured-like data with effects hidden in it: the scene simulated under its model
    /// plus the hidden effects, filmed with camera noise and dropped frames.
    Synth(synth::Args),
    /// Find where simulation and measurement disagree, name the missing physical effects from
    /// the catalogue, add them and show the gap shrink.
    Discrepancy(discrepancy::Args),
    /// Plan a shot: the strike that pots a ball and leaves the cue ball nearest a target
    /// (thesis chapter 7), ranked by its pot probability under execution noise.
    Plan(plan::Args),
    /// Simulate many scenes on every core (a directory of scene files or a JSON-lines file);
    /// results as JSON lines or a Parquet table. Exits with 1 if any scene failed.
    Batch(batch::Args),
    /// Referee a frame of snooker: simulate the frame's strike, judge it by the rules (WPBSA),
    /// write the verdict and the next frame; several frames play a sequence of strokes.
    Referee(referee::Args),
    /// Play snooker from a frame file: stroke after stroke chosen by the player (candidate pots
    /// of every kind, valued by the position they leave, sampled under execution noise) and
    /// played with the noise, for one visit or the whole frame; the play log, a summary, a
    /// recording.
    Play(play::Args),
    /// The shot lab: a local web page to set up a position, strike, plan a shot and play a
    /// frame (bound to the loopback address unless --host says otherwise).
    Serve(serve::Args),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) if !e.use_stderr() => {
            // --help and --version.
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
        Err(e) => {
            // One line: clap's message up to its first blank line (the usage and tips after
            // it are left out), with where to find the usage.
            let text = e.render().to_string();
            let message: Vec<&str> = text
                .lines()
                .take_while(|l| !l.trim().is_empty())
                .map(str::trim)
                .collect();
            let message = message.join(" ");
            let message = message.strip_prefix("error: ").unwrap_or(&message);
            return cmd::bad_input(format!("{message} (see --help)"));
        }
    };
    match cli.command {
        Command::Simulate(a) => simulate::run(a),
        Command::Impact(a) => impact::run(a),
        Command::Validate(a) => validate::run_command(a),
        Command::Synth(a) => synth::run(a),
        Command::Discrepancy(a) => discrepancy::run(a),
        Command::Plan(a) => plan::run(a),
        Command::Batch(a) => batch::run(a),
        Command::Referee(a) => referee::run(a),
        Command::Play(a) => play::run(a),
        Command::Serve(a) => serve::run(a),
    }
}
