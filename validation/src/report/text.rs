//! The terminal table of `snooker validate`: one line per run, then each compared run's
//! figures.

use super::{Report, information_cell, sci, sequence_cell, stretches_cell};
use crate::compare::{Comparison, Figure};
use crate::crosscheck::{Compared, Method, RunOutcome};
use std::fmt::Write as _;

fn figure_line(f: &Figure) -> String {
    format!(
        "    {:<26} {:<40} ours {:>11.6} rapier {:>11.6} diff {:>9} tol {:>9} {}",
        f.kind.name(),
        f.at,
        f.ours,
        f.rapier,
        sci(f.diff),
        sci(f.tol),
        if f.pass() { "ok" } else { "FAIL" }
    )
}

/// The terminal table: one line per run, then each compared run's figures.
pub fn text(report: &Report) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<20} {:<13} {:<11} {:<24} {:<7} details",
        "scene", "models", "method", "impacts", "verdict"
    );
    for r in &report.runs {
        let (method, seq, detail) = match &r.outcome {
            RunOutcome::Compared(c) => (
                c.method.name(),
                match c.method {
                    Method::WholeShot => sequence_cell(&c.whole),
                    Method::Stretches => format!("{} stretches", stretches_cell(&c.stretches)),
                },
                format!("sink {} m", sci(c.sink)),
            ),
            RunOutcome::Skipped { reason } | RunOutcome::Failed { reason } => {
                ("-", "-".into(), reason.clone())
            }
        };
        let _ = writeln!(
            out,
            "{:<20} {:<13} {:<11} {:<24} {:<7} {detail}",
            r.scene,
            r.models.name(),
            method,
            seq,
            r.verdict().word()
        );
        if let Some(c) = r.compared() {
            text_compared(&mut out, c);
        }
        for s in &r.statistics {
            let _ = writeln!(
                out,
                "    statistic {:<30} ours {:.3} +- {:.3} [{:.3}, {:.3}]  rapier {:.3}",
                s.name, s.ours_mean, s.ours_sd, s.ours_min, s.ours_max, s.rapier
            );
        }
    }
    let c = report.counts();
    let _ = writeln!(
        out,
        "\n{} runs compared at dt = {} s: {} passed, {} failed; {} skipped",
        c.compared, report.dt, c.passed, c.failed, c.skipped
    );
    out
}

fn text_sequences(out: &mut String, c: &Comparison, indent: &str) {
    if !c.sequence_match {
        let _ = writeln!(out, "{indent}ours:   {}", c.labels_ours().join(", "));
        let _ = writeln!(out, "{indent}rapier: {}", c.labels_rapier().join(", "));
    }
}

fn text_compared(out: &mut String, c: &Compared) {
    match c.method {
        Method::WholeShot => {
            for f in &c.whole.figures {
                let _ = writeln!(out, "{}", figure_line(f));
            }
            text_sequences(out, &c.whole, "    ");
        }
        Method::Stretches => {
            for (k, s) in c.stretches.iter().enumerate() {
                let _ = writeln!(
                    out,
                    "  stretch {} from {:.6} s (after {}): {} {}{}",
                    k + 1,
                    s.from,
                    s.after,
                    sequence_cell(&s.comparison),
                    if s.pass() { "ok" } else { "FAIL" },
                    if s.rapier_finished {
                        ""
                    } else {
                        " (rapier ran out of time)"
                    }
                );
                for f in &s.comparison.figures {
                    let _ = writeln!(out, "{}", figure_line(f));
                }
                text_sequences(out, &s.comparison, "    ");
            }
            let _ = writeln!(
                out,
                "  whole shot (information): {}",
                information_cell(&c.whole)
            );
            text_sequences(out, &c.whole, "    ");
        }
    }
}
