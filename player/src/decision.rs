//! What an agent decides for one stroke: where the cue ball in hand goes, the nomination, the
//! strike meant, and what was planned (for the play log).

use serde::Serialize;
use snooker_engine::Cue;
use snooker_planner::ShotKind;
use snooker_rules::Colour;

/// The kind of stroke planned: a pot of one of the planner's kinds, or a safety.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PlanKind {
    /// Cue ball -> ball on -> pocket.
    Direct,
    /// The ball on off one or two cushions into the pocket.
    Double,
    /// Cue ball -> a ball on -> the ball potted.
    Plant,
    /// The ball on glancing off another ball into the pocket.
    Kiss,
    /// No pot: the ball on hit, the opponent left the least.
    Safety,
}

impl From<ShotKind> for PlanKind {
    fn from(k: ShotKind) -> PlanKind {
        match k {
            ShotKind::Direct => PlanKind::Direct,
            ShotKind::Double => PlanKind::Double,
            ShotKind::Plant => PlanKind::Plant,
            ShotKind::Kiss => PlanKind::Kiss,
        }
    }
}

impl PlanKind {
    /// Its name in the play log.
    pub fn name(self) -> &'static str {
        match self {
            PlanKind::Direct => "direct",
            PlanKind::Double => "double",
            PlanKind::Plant => "plant",
            PlanKind::Kiss => "kiss",
            PlanKind::Safety => "safety",
        }
    }
}

/// A stroke considered, as the play log lists it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Considered {
    /// The ball meant to be potted (its id); `""` for a safety.
    pub pot: String,
    /// The pocket (`""` for a safety).
    pub pocket: String,
    /// The kind.
    pub kind: PlanKind,
    /// Share of the noise samples that potted the ball legally (0 for a safety).
    pub pot_probability: f64,
    /// Where the cue ball stops when the strike is played exactly, m.
    pub cue_to: [f64; 2],
    /// The ball the cue ball is sent at first (the ball potted, a plant's first ball, the
    /// ball a safety is played off).
    pub ball: String,
    /// The ball planted through, kissed off, or the double's cushions.
    pub via: Vec<String>,
    /// Expected value of the stroke in points (samples' mean), to the player.
    pub value: f64,
    /// Noise samples simulated for it.
    pub samples: usize,
}

/// One stroke decided.
#[derive(Debug, Clone, PartialEq)]
pub struct Decision {
    /// Where the cue ball in hand is placed (plan, m); None when not in hand.
    pub placement: Option<[f64; 2]>,
    /// The colour nominated (or the free ball), if any.
    pub nominated: Option<Colour>,
    /// The strike meant.
    pub strike: Cue,
    /// What the strike was planned as.
    pub plan: Considered,
    /// The next best strokes considered, best first.
    pub alternatives: Vec<Considered>,
    /// Shots simulated to decide.
    pub shots: u64,
}
