//! The player's safeties where a direct stroke fouls: a snooker escaped off a cushion, a
//! touching ball on played away from (WPBSA Section 3 Rule 8(c)). The frames are the rules'
//! own (`rules/tests/frames/`); on the old player (direct safeties only, then the nearest ball
//! on struck full) both strokes were fouls: first_hit_not_on and push_stroke.

use snooker_planner::Noise;
use snooker_player::game::with_choices;
use snooker_player::{Agent, Context, Decision, PlanKind, Player};
use snooker_rules::{Frame, Verdict};
use std::path::Path;

fn frame(name: &str) -> Frame {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../rules/tests/frames/{name}.toml"));
    snooker_rules::load(&path)
        .unwrap_or_else(|e| panic!("{e}"))
        .frame
}

/// The player's decision (standard noise, effort 2000) and its strike's verdict played as
/// meant.
fn decide(f: &Frame) -> (Decision, Verdict) {
    let ctx = Context {
        noise: Noise::STANDARD,
        seed: 3,
        stroke: 1,
        effort: 2000,
        watch: Default::default(),
    };
    let d = Player.choose(f, &ctx).unwrap();
    let chosen = with_choices(f, &d).unwrap();
    let v = chosen.play(&d.strike).unwrap().verdict;
    (d, v)
}

#[test]
fn a_snookered_player_escapes_off_a_cushion() {
    // The cue ball behind the black, the pink on beyond it: every direct stroke at the pink
    // meets the black first.
    let (d, v) = decide(&frame("free_ball_awarded"));
    assert!(v.legal(), "the escape fouls: {v:?}");
    assert_eq!(d.plan.kind, PlanKind::Safety);
    assert_eq!(d.plan.ball, "pink");
    assert!(!d.plan.via.is_empty(), "no cushion named: {:?}", d.plan);
    assert!(d.plan.samples > 0);
}

#[test]
fn a_touching_ball_on_is_played_away_from() {
    let f = frame("touching_red_pushed");
    assert!(
        !f.touching().is_empty(),
        "the frame's cue ball touches no ball"
    );
    let (d, v) = decide(&f);
    assert!(v.legal(), "the stroke fouls: {v:?}");
    assert_eq!(d.plan.kind, PlanKind::Safety);
}
