//! Figure-by-figure comparison of two records of the same scene against the tolerances of
//! [`crate::tolerance`].

use crate::record::{Contact, Record};
use crate::tolerance::Allowances;
use serde::Serialize;

/// One compared figure: the worst case over the events it covers (largest difference relative
/// to its tolerance).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Figure {
    /// What is compared.
    pub name: &'static str,
    /// Unit of the values.
    pub unit: &'static str,
    /// Which event or ball the worst case is.
    pub at: String,
    /// Our engine's value there.
    pub ours: f64,
    /// rapier's value there.
    pub rapier: f64,
    /// The difference (a vector norm for vector quantities).
    pub diff: f64,
    /// The tolerance there.
    pub tol: f64,
}

impl Figure {
    /// True when the difference is within the tolerance.
    pub fn pass(&self) -> bool {
        self.diff <= self.tol
    }
}

/// The comparison of one run.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Comparison {
    /// Our engine's impacts, labelled, in order.
    pub sequence_ours: Vec<String>,
    /// rapier's impacts, labelled, in order.
    pub sequence_rapier: Vec<String>,
    /// Number of leading impacts compared (all of them unless the scene is chaotic).
    pub compared: usize,
    /// True when the compared impacts are the same, in the same order.
    pub sequence_match: bool,
    /// The figures.
    pub figures: Vec<Figure>,
}

impl Comparison {
    /// True when the sequences match and every figure is within its tolerance.
    pub fn pass(&self) -> bool {
        self.sequence_match && self.figures.iter().all(Figure::pass)
    }
}

/// Keeps, among candidate figures, the one with the largest difference relative to its
/// tolerance.
fn worst(cands: impl IntoIterator<Item = Figure>) -> Option<Figure> {
    let ratio = |f: &Figure| {
        if f.tol > 0.0 {
            f.diff / f.tol
        } else if f.diff > 0.0 {
            f64::INFINITY
        } else {
            0.0
        }
    };
    cands
        .into_iter()
        .max_by(|a, b| ratio(a).total_cmp(&ratio(b)))
}

/// What of a run is compared.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scope {
    /// Only the first this many impacts, and no transitions or final positions (a chaotic
    /// scene); everything when `None`.
    pub impacts: Option<usize>,
    /// Balls whose states after impacts are not compared (in a chaotic scene, the balls of a
    /// pack: rapier solves their contacts together within the step of the first impact).
    pub skip_after: Vec<usize>,
}

/// Compares `rapier` with `ours` within `scope`, with the tolerances `tol` (derived from
/// `ours`).
pub fn compare(ours: &Record, rapier: &Record, tol: &Allowances, scope: &Scope) -> Comparison {
    let limit = scope.impacts;
    let label =
        |r: &Record| -> Vec<String> { r.impacts.iter().map(|i| i.contact.label(&r.ids)).collect() };
    let n = limit.unwrap_or(usize::MAX);
    let ours_n = ours.impacts.len().min(n);
    let rapier_n = rapier.impacts.len().min(n);
    let common = ours.impacts[..ours_n]
        .iter()
        .zip(&rapier.impacts[..rapier_n])
        .take_while(|(a, b)| a.contact == b.contact)
        .count();
    let sequence_match = common == ours_n && common == rapier_n;
    let mut figures = Vec::new();
    let pairs = || {
        ours.impacts
            .iter()
            .zip(&rapier.impacts)
            .enumerate()
            .take(common)
    };
    let name_of = |k: usize| format!("#{} {}", k + 1, ours.impacts[k].contact.label(&ours.ids));
    figures.extend(worst(pairs().map(|(k, (a, b))| Figure {
        name: "impact time",
        unit: "s",
        at: name_of(k),
        ours: a.t,
        rapier: b.t,
        diff: (a.t - b.t).abs(),
        tol: tol.impacts[k].t,
    })));
    let (vel, spin) = after_figures(ours, rapier, tol, common, &scope.skip_after);
    figures.extend(worst(vel));
    figures.extend(worst(spin));
    if limit.is_none() {
        figures.extend(compare_rolls(ours, rapier, tol));
        figures.extend(compare_finals(ours, rapier, tol));
    }
    Comparison {
        sequence_ours: label(ours),
        sequence_rapier: label(rapier),
        compared: ours_n,
        sequence_match,
        figures,
    }
}

/// Velocity and spin figures of every ball after each of the first `n` impacts (pots and
/// the balls of `skip` left out).
fn after_figures(
    ours: &Record,
    rapier: &Record,
    tol: &Allowances,
    n: usize,
    skip: &[usize],
) -> (Vec<Figure>, Vec<Figure>) {
    let mut vel = Vec::new();
    let mut spin = Vec::new();
    for (k, (a, b)) in ours.impacts.iter().zip(&rapier.impacts).enumerate().take(n) {
        if matches!(a.contact, Contact::Pocket(..)) {
            continue;
        }
        for (j, &ball) in a.contact.balls().iter().enumerate() {
            if skip.contains(&ball) {
                continue;
            }
            let at = format!(
                "#{} {} ({})",
                k + 1,
                a.contact.label(&ours.ids),
                ours.ids[ball]
            );
            let (x, y) = (a.after[j], b.after[j]);
            vel.push(Figure {
                name: "velocity after impact",
                unit: "m/s",
                at: at.clone(),
                ours: x.vel.norm(),
                rapier: y.vel.norm(),
                diff: (x.vel - y.vel).norm(),
                tol: tol.impacts[k].vel,
            });
            spin.push(Figure {
                name: "spin after impact",
                unit: "rad/s",
                at,
                ours: x.spin.norm(),
                rapier: y.spin.norm(),
                diff: (x.spin - y.spin).norm(),
                tol: tol.impacts[k].spin,
            });
        }
    }
    (vel, spin)
}

/// Slide-to-roll times and speeds, the k-th roll of each ball against the k-th; a ball that
/// rolls a different number of times is a failed figure.
fn compare_rolls(ours: &Record, rapier: &Record, tol: &Allowances) -> Vec<Figure> {
    let mut times = Vec::new();
    let mut speeds = Vec::new();
    let mut count = None;
    for ball in 0..ours.ids.len() {
        let a: Vec<_> = ours
            .rolls
            .iter()
            .enumerate()
            .filter(|(_, r)| r.ball == ball)
            .collect();
        let b: Vec<_> = rapier.rolls.iter().filter(|r| r.ball == ball).collect();
        if a.len() != b.len() && count.is_none() {
            count = Some(Figure {
                name: "slide-to-roll count",
                unit: "",
                at: ours.ids[ball].clone(),
                ours: a.len() as f64,
                rapier: b.len() as f64,
                diff: (a.len() as f64 - b.len() as f64).abs(),
                tol: 0.0,
            });
        }
        for (k, ((i, ra), rb)) in a.iter().zip(&b).enumerate() {
            let at = format!("{} roll {}", ours.ids[ball], k + 1);
            times.push(Figure {
                name: "slide-to-roll time",
                unit: "s",
                at: at.clone(),
                ours: ra.t,
                rapier: rb.t,
                diff: (ra.t - rb.t).abs(),
                tol: tol.rolls[*i].t,
            });
            speeds.push(Figure {
                name: "slide-to-roll speed",
                unit: "m/s",
                at,
                ours: ra.speed,
                rapier: rb.speed,
                diff: (ra.speed - rb.speed).abs(),
                tol: tol.rolls[*i].speed,
            });
        }
    }
    count
        .into_iter()
        .chain(worst(times))
        .chain(worst(speeds))
        .collect()
}

/// Final positions in plan (rapier's balls rest `sink` lower, by design), and pots.
fn compare_finals(ours: &Record, rapier: &Record, tol: &Allowances) -> Vec<Figure> {
    let cands = ours
        .finals
        .iter()
        .zip(&rapier.finals)
        .enumerate()
        .map(|(i, (a, b))| {
            let (diff, t) = if a.pocket.is_some() || b.pocket.is_some() {
                // Pots are compared in the sequence; a ball pocketed in one engine only is a fail.
                let same = a.pocket == b.pocket;
                (if same { 0.0 } else { f64::INFINITY }, 0.0)
            } else {
                ((a.pos.xy() - b.pos.xy()).norm(), tol.finals[i])
            };
            Figure {
                name: "final position",
                unit: "m",
                at: ours.ids[i].clone(),
                ours: a.pos.xy().norm(),
                rapier: b.pos.xy().norm(),
                diff,
                tol: t,
            }
        });
    worst(cands).into_iter().collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::record::{Final, Impact, Velocities};
    use snooker_engine::Vec3;

    fn record(t: f64, v: f64, end: f64) -> Record {
        let k = Velocities {
            vel: Vec3::new(v, 0.0, 0.0),
            spin: Vec3::zeros(),
        };
        Record {
            ids: vec!["cue".into(), "red".into()],
            impacts: vec![Impact {
                t,
                contact: Contact::Balls(0, 1),
                after: vec![k, k],
                approach: 1.0,
            }],
            rolls: vec![],
            finals: vec![
                Final {
                    pos: Vec3::new(end, 0.0, 0.0262),
                    pocket: None,
                },
                Final {
                    pos: Vec3::new(1.0, 0.0, 0.0262),
                    pocket: None,
                },
            ],
            duration: 1.0,
        }
    }

    fn tol() -> Allowances {
        Allowances {
            impacts: vec![crate::tolerance::ImpactTol {
                t: 1e-4,
                vel: 1e-3,
                spin: 1e-2,
            }],
            rolls: vec![],
            finals: vec![1e-3, 1e-3],
        }
    }

    #[test]
    fn within_tolerance_passes_and_beyond_fails() {
        let c = compare(
            &record(0.1, 1.0, 0.5),
            &record(0.10005, 1.0005, 0.5005),
            &tol(),
            &Scope::default(),
        );
        assert!(c.pass(), "{c:?}");
        let c = compare(
            &record(0.1, 1.0, 0.5),
            &record(0.1, 1.0, 0.502),
            &tol(),
            &Scope::default(),
        );
        assert!(!c.pass());
        let f = c
            .figures
            .iter()
            .find(|f| f.name == "final position")
            .unwrap();
        assert!((f.diff - 0.002).abs() < 1e-12 && f.at == "cue");
    }

    #[test]
    fn a_different_sequence_fails() {
        let mut other = record(0.1, 1.0, 0.5);
        other.impacts[0].contact = Contact::Cushion(0, "top".into());
        let c = compare(&record(0.1, 1.0, 0.5), &other, &tol(), &Scope::default());
        assert!(!c.sequence_match && !c.pass());
    }
}
