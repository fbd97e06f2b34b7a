//! Figure-by-figure comparison of two digests of the same scene (or of the same stretch of
//! it) against the tolerances of [`crate::tolerance`].

use crate::digest::{ImpactDigest, Parties, ShotDigest};
use crate::tolerance::{Allowances, Budget, change_bound};
use serde::Serialize;

/// What a figure measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FigureKind {
    /// When an impact (or pot, or landing) happens.
    ImpactTime,
    /// Each ball's velocity just after an impact.
    VelocityAfter,
    /// Each ball's spin just after an impact.
    SpinAfter,
    /// Each ball's velocity just before the impact that ends a stretch.
    VelocityBefore,
    /// Each ball's spin just before the impact that ends a stretch.
    SpinBefore,
    /// The change of each ball's velocity at the impact that ends a stretch.
    VelocityChange,
    /// The change of each ball's spin at the impact that ends a stretch.
    SpinChange,
    /// How many times a ball starts rolling.
    RollCount,
    /// When a ball starts rolling.
    RollTime,
    /// A ball's speed when it starts rolling.
    RollSpeed,
    /// Where a ball ends, in plan.
    FinalPosition,
}

impl FigureKind {
    /// Its name in reports.
    pub const fn name(self) -> &'static str {
        match self {
            FigureKind::ImpactTime => "impact time",
            FigureKind::VelocityAfter => "velocity after impact",
            FigureKind::SpinAfter => "spin after impact",
            FigureKind::VelocityBefore => "velocity before impact",
            FigureKind::SpinBefore => "spin before impact",
            FigureKind::VelocityChange => "velocity change at impact",
            FigureKind::SpinChange => "spin change at impact",
            FigureKind::RollCount => "slide-to-roll count",
            FigureKind::RollTime => "slide-to-roll time",
            FigureKind::RollSpeed => "slide-to-roll speed",
            FigureKind::FinalPosition => "final position",
        }
    }

    /// Unit of its values.
    pub const fn unit(self) -> &'static str {
        match self {
            FigureKind::ImpactTime | FigureKind::RollTime => "s",
            FigureKind::VelocityAfter
            | FigureKind::VelocityBefore
            | FigureKind::VelocityChange
            | FigureKind::RollSpeed => "m/s",
            FigureKind::SpinAfter | FigureKind::SpinBefore | FigureKind::SpinChange => "rad/s",
            FigureKind::RollCount => "",
            FigureKind::FinalPosition => "m",
        }
    }

    /// True for the impact's own difference, bounded by what the impact models allow by
    /// design rather than by the motion's tolerances.
    pub const fn is_impact_change(self) -> bool {
        matches!(self, FigureKind::VelocityChange | FigureKind::SpinChange)
    }
}

/// One compared figure: the worst case over the events it covers (largest difference relative
/// to its tolerance).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Figure {
    /// What is compared.
    pub kind: FigureKind,
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

    /// The difference over the tolerance (infinite for a difference where none is allowed).
    pub fn ratio(&self) -> f64 {
        if self.tol > 0.0 {
            self.diff / self.tol
        } else if self.diff > 0.0 {
            f64::INFINITY
        } else {
            0.0
        }
    }
}

/// The comparison of one run, or of one stretch of a run.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Comparison {
    /// Ball ids, in the scene's order.
    pub ids: Vec<String>,
    /// Our engine's impacts, in order.
    pub ours: Vec<Parties>,
    /// rapier's impacts, in order.
    pub rapier: Vec<Parties>,
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

    /// The figure of this kind, if the comparison has one.
    pub fn figure(&self, kind: FigureKind) -> Option<&Figure> {
        self.figures.iter().find(|f| f.kind == kind)
    }

    /// Our engine's impacts as labels.
    pub fn labels_ours(&self) -> Vec<String> {
        self.ours.iter().map(|c| c.label(&self.ids)).collect()
    }

    /// rapier's impacts as labels.
    pub fn labels_rapier(&self) -> Vec<String> {
        self.rapier.iter().map(|c| c.label(&self.ids)).collect()
    }
}

/// Keeps, among candidate figures, the one with the largest difference relative to its
/// tolerance.
fn worst(cands: impl IntoIterator<Item = Figure>) -> Option<Figure> {
    cands
        .into_iter()
        .max_by(|a, b| a.ratio().total_cmp(&b.ratio()))
}

/// How a compared run or stretch ends.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum End {
    /// At rest: every impact's state after, the slide-to-roll transitions and the final
    /// positions are compared.
    #[default]
    Rest,
    /// At an impact (a stretch ends at the next impact whose models differ by design): the
    /// state just before that last impact and its change are compared instead of its state
    /// after, and no final positions.
    Impact,
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
    /// How the compared run ends.
    pub end: End,
}

/// Compares `rapier` with `ours` within `scope`, with the tolerances `tol` (derived from
/// `ours`) and, for an impact ending a stretch, the bounds of `budget`.
pub fn compare(
    ours: &ShotDigest,
    rapier: &ShotDigest,
    tol: &Allowances,
    budget: &Budget,
    scope: &Scope,
) -> Comparison {
    let limit = scope.impacts;
    let n = limit.unwrap_or(usize::MAX);
    let ours_n = ours.impacts.len().min(n);
    let rapier_n = rapier.impacts.len().min(n);
    let common = ours.impacts[..ours_n]
        .iter()
        .zip(&rapier.impacts[..rapier_n])
        .take_while(|(a, b)| a.parties == b.parties)
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
    let name_of = |k: usize| format!("#{} {}", k + 1, ours.impacts[k].parties.label(&ours.ids));
    figures.extend(worst(pairs().map(|(k, (a, b))| Figure {
        kind: FigureKind::ImpactTime,
        at: name_of(k),
        ours: a.t,
        rapier: b.t,
        diff: (a.t - b.t).abs(),
        tol: tol.impacts[k].t,
    })));
    // The impact ending a stretch: compared before and across, not after.
    let closing = (scope.end == End::Impact && ours_n > 0 && common == ours_n)
        .then(|| ours_n - 1)
        .filter(|&k| !ours.impacts[k].parties.is_pot());
    let after_n = closing.unwrap_or(common);
    let states = |before: bool, range: std::ops::Range<usize>| {
        state_figures(ours, rapier, tol, range, &scope.skip_after, before)
    };
    let (vel, spin) = states(false, 0..after_n);
    figures.extend(worst(vel));
    figures.extend(worst(spin));
    if let Some(k) = closing {
        let (vel, spin) = states(true, k..k + 1);
        figures.extend(worst(vel));
        figures.extend(worst(spin));
        let (vel, spin) = change_figures(ours, rapier, tol, k, budget, &scope.skip_after);
        figures.extend(worst(vel));
        figures.extend(worst(spin));
    }
    if limit.is_none() {
        figures.extend(compare_rolls(ours, rapier, tol));
        if scope.end == End::Rest {
            figures.extend(compare_finals(ours, rapier, tol));
        }
    }
    Comparison {
        ids: ours.ids.clone(),
        ours: ours.impacts.iter().map(|i| i.parties.clone()).collect(),
        rapier: rapier.impacts.iter().map(|i| i.parties.clone()).collect(),
        compared: ours_n,
        sequence_match,
        figures,
    }
}

/// "#k label (ball)" for ball `ball` at impact `k`.
fn at_label(ours: &ShotDigest, k: usize, ball: usize) -> String {
    format!(
        "#{} {} ({})",
        k + 1,
        ours.impacts[k].parties.label(&ours.ids),
        ours.ids[ball]
    )
}

/// Velocity and spin figures of every ball just after (or just `before`) each impact of
/// `range` (pots and the balls of `skip` left out).
fn state_figures(
    ours: &ShotDigest,
    rapier: &ShotDigest,
    tol: &Allowances,
    range: std::ops::Range<usize>,
    skip: &[usize],
    before: bool,
) -> (Vec<Figure>, Vec<Figure>) {
    let mut vel = Vec::new();
    let mut spin = Vec::new();
    let (kv, kw) = if before {
        (FigureKind::VelocityBefore, FigureKind::SpinBefore)
    } else {
        (FigureKind::VelocityAfter, FigureKind::SpinAfter)
    };
    for k in range {
        let (a, b) = (&ours.impacts[k], &rapier.impacts[k]);
        if a.parties.is_pot() {
            continue;
        }
        let t = &tol.impacts[k];
        let (tv, tw) = if before {
            (t.vel_before, t.spin_before)
        } else {
            (t.vel, t.spin)
        };
        let (sa, sb) = if before {
            (&a.before, &b.before)
        } else {
            (&a.after, &b.after)
        };
        for (j, &ball) in a.parties.balls().iter().enumerate() {
            if skip.contains(&ball) {
                continue;
            }
            let at = at_label(ours, k, ball);
            let (x, y) = (sa[j], sb[j]);
            vel.push(Figure {
                kind: kv,
                at: at.clone(),
                ours: x.vel.norm(),
                rapier: y.vel.norm(),
                diff: (x.vel - y.vel).norm(),
                tol: tv,
            });
            spin.push(Figure {
                kind: kw,
                at,
                ours: x.spin.norm(),
                rapier: y.spin.norm(),
                diff: (x.spin - y.spin).norm(),
                tol: tw,
            });
        }
    }
    (vel, spin)
}

/// The impact's own difference at impact `k`: how much more or less each engine changed each
/// ball's velocity and spin, against the bound of [`change_bound`].
fn change_figures(
    ours: &ShotDigest,
    rapier: &ShotDigest,
    tol: &Allowances,
    k: usize,
    budget: &Budget,
    skip: &[usize],
) -> (Vec<Figure>, Vec<Figure>) {
    let (a, b): (&ImpactDigest, &ImpactDigest) = (&ours.impacts[k], &rapier.impacts[k]);
    let incoming = a
        .before
        .iter()
        .zip(&b.before)
        .map(|(x, y)| (x.vel - y.vel).norm())
        .fold(0.0, f64::max);
    let (tv, tw) = change_bound(budget, a, b, incoming, tol.impacts[k].lateral);
    let mut vel = Vec::new();
    let mut spin = Vec::new();
    for (j, &ball) in a.parties.balls().iter().enumerate() {
        if skip.contains(&ball) {
            continue;
        }
        let at = at_label(ours, k, ball);
        let dv_a = a.after[j].vel - a.before[j].vel;
        let dv_b = b.after[j].vel - b.before[j].vel;
        let dw_a = a.after[j].spin - a.before[j].spin;
        let dw_b = b.after[j].spin - b.before[j].spin;
        vel.push(Figure {
            kind: FigureKind::VelocityChange,
            at: at.clone(),
            ours: dv_a.norm(),
            rapier: dv_b.norm(),
            diff: (dv_a - dv_b).norm(),
            tol: tv,
        });
        spin.push(Figure {
            kind: FigureKind::SpinChange,
            at,
            ours: dw_a.norm(),
            rapier: dw_b.norm(),
            diff: (dw_a - dw_b).norm(),
            tol: tw,
        });
    }
    (vel, spin)
}

/// Slide-to-roll times and speeds, the k-th roll of each ball against the k-th; a ball that
/// rolls a different number of times is a failed figure.
fn compare_rolls(ours: &ShotDigest, rapier: &ShotDigest, tol: &Allowances) -> Vec<Figure> {
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
                kind: FigureKind::RollCount,
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
                kind: FigureKind::RollTime,
                at: at.clone(),
                ours: ra.t,
                rapier: rb.t,
                diff: (ra.t - rb.t).abs(),
                tol: tol.rolls[*i].t,
            });
            speeds.push(Figure {
                kind: FigureKind::RollSpeed,
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
fn compare_finals(ours: &ShotDigest, rapier: &ShotDigest, tol: &Allowances) -> Vec<Figure> {
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
                kind: FigureKind::FinalPosition,
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
    use crate::digest::{Final, ImpactDigest, Velocities};
    use snooker_engine::Params;
    use snooker_engine::Vec3;

    fn digest(t: f64, v: f64, end: f64) -> ShotDigest {
        let k = Velocities {
            vel: Vec3::new(v, 0.0, 0.0),
            spin: Vec3::zeros(),
        };
        ShotDigest {
            ids: vec!["cue".into(), "red".into()],
            start: vec![k, k],
            impacts: vec![ImpactDigest {
                t,
                parties: Parties::Balls(0, 1),
                before: vec![k, k],
                after: vec![k, k],
                end: t,
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
                vel_before: 1e-3,
                spin_before: 1e-2,
                lateral: 0.0,
            }],
            rolls: vec![],
            finals: vec![1e-3, 1e-3],
        }
    }

    fn budget() -> Budget {
        Budget {
            dt: 1e-4,
            sink: 7e-5,
            friction: true,
            level_cushions: false,
            nose_radius: 0.0078,
            jaw_contact: 0.034,
            params: Params::default(),
        }
    }

    #[test]
    fn within_tolerance_passes_and_beyond_fails() {
        let c = compare(
            &digest(0.1, 1.0, 0.5),
            &digest(0.10005, 1.0005, 0.5005),
            &tol(),
            &budget(),
            &Scope::default(),
        );
        assert!(c.pass(), "{c:?}");
        let c = compare(
            &digest(0.1, 1.0, 0.5),
            &digest(0.1, 1.0, 0.502),
            &tol(),
            &budget(),
            &Scope::default(),
        );
        assert!(!c.pass());
        let f = c.figure(FigureKind::FinalPosition).unwrap();
        assert!((f.diff - 0.002).abs() < 1e-12 && f.at == "cue");
    }

    #[test]
    fn a_different_sequence_fails() {
        let mut other = digest(0.1, 1.0, 0.5);
        other.impacts[0].parties = Parties::Cushion(0, "top".into());
        let c = compare(
            &digest(0.1, 1.0, 0.5),
            &other,
            &tol(),
            &budget(),
            &Scope::default(),
        );
        assert!(!c.sequence_match && !c.pass());
    }

    #[test]
    fn a_stretch_compares_its_last_impact_before_and_across() {
        let ours = digest(0.1, 1.0, 0.5);
        let mut rapier = digest(0.10005, 1.0005, 0.7);
        let scope = Scope {
            end: End::Impact,
            ..Scope::default()
        };
        let c = compare(&ours, &rapier, &tol(), &budget(), &scope);
        let kinds: Vec<FigureKind> = c.figures.iter().map(|f| f.kind).collect();
        assert_eq!(
            kinds,
            [
                FigureKind::ImpactTime,
                FigureKind::VelocityBefore,
                FigureKind::SpinBefore,
                FigureKind::VelocityChange,
                FigureKind::SpinChange,
            ]
        );
        assert!(c.pass(), "{c:?}");
        // A change far beyond what friction allows at 1 m/s fails, whatever the state before.
        rapier.impacts[0].after[0].vel.x = -2.0;
        let c = compare(&ours, &rapier, &tol(), &budget(), &scope);
        assert!(!c.figure(FigureKind::VelocityChange).unwrap().pass());
    }
}
