//! One named test per rule, each with its minimal frame file (`rules/tests/frames/`): the
//! strike simulated by the engine, judged, and every field of the verdict that the rule decides
//! checked, with the next frame (formats.md, "Frame" and "Referee result"; WPBSA rules as
//! docs/rules.md cites them).

use snooker_engine::{BallState, EventKind, Params, SnookerDims, Vec3, simulate};
use snooker_rules::file::FrameFile;
use snooker_rules::respot::{self, spot};
use snooker_rules::snookered;
use snooker_rules::{Colour, FoulReason, Frame, Next, On, Verdict};
use std::path::Path;

fn load(name: &str) -> FrameFile {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("tests/frames/{name}.toml"));
    snooker_rules::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

/// The frame file's strike, simulated from the scene the file is and judged; the scene and the
/// frame must give the engine the same setup.
fn play(name: &str) -> (FrameFile, Verdict) {
    let f = load(name);
    let strike = f.strike.expect("a strike");
    let setup = f.frame.setup(&strike).unwrap();
    assert_eq!(
        setup, f.scene.setup,
        "{name}: the frame and the scene differ"
    );
    let shot = simulate(&setup, f.frame.options()).unwrap();
    let v = f
        .frame
        .judge(&shot)
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    (f, v)
}

fn foul(v: &Verdict) -> (FoulReason, u32) {
    let f = v.foul.as_ref().expect("a foul");
    (f.reason, f.points)
}

fn next(f: &FrameFile, v: &Verdict) -> Frame {
    match f.frame.next(v) {
        Next::Play(n) => *n,
        Next::Over { .. } => panic!("the frame is over"),
    }
}

fn pos_of(frame: &Frame, id: &str) -> Option<Vec3> {
    frame
        .balls()
        .iter()
        .find(|b| b.id == id)
        .map(|b| b.state.pos)
}

fn respotted(v: &Verdict) -> Vec<(&str, [f64; 2])> {
    v.respotted
        .iter()
        .map(|(id, r)| (id.as_str(), [r.pos.x, r.pos.y]))
        .collect()
}

const R: f64 = 0.0262;

// ---- Fouls, in the contract's order ----

#[test]
fn no_ball_hit_is_worth_the_ball_on() {
    let (f, v) = play("no_ball_hit");
    assert_eq!(foul(&v), (FoulReason::NoBallHit, 6));
    assert_eq!(v.first_hit, None);
    assert_eq!(v.scores, [20, 36]);
    let n = next(&f, &v);
    assert_eq!(
        (n.state().to_play, n.state().on),
        (1, On::Closing(Colour::Pink))
    );
}

#[test]
fn first_hit_not_on_is_worth_the_ball_hit() {
    let (f, v) = play("first_hit_not_on");
    assert_eq!(foul(&v), (FoulReason::FirstHitNotOn, 5));
    assert_eq!(v.first_hit.as_deref(), Some("blue"));
    assert_eq!((v.points, v.scores), (0, [12, 5]));
    assert_eq!(next(&f, &v).state().on, On::Red);
}

#[test]
fn hitting_a_ball_not_on_at_the_same_instant_as_one_on_is_a_foul() {
    let (_, v) = play("simultaneous_not_on");
    assert_eq!(foul(&v), (FoulReason::FirstHitNotOn, 4));
    assert_eq!(v.first_hit.as_deref(), Some("yellow"));
}

#[test]
fn two_reds_hit_at_the_same_instant_are_no_foul() {
    let f = load("simultaneous_two_reds");
    let shot = simulate(&f.scene.setup, &f.scene.options).unwrap();
    // Both contacts within the contract's 1e-9 s.
    let hits: Vec<f64> = shot
        .events
        .iter()
        .filter(|e| e.kind == EventKind::BallBall && e.balls.contains(&0))
        .map(|e| e.t)
        .take(2)
        .collect();
    assert!((hits[1] - hits[0]).abs() <= 1e-9, "{hits:?}");
    let v = f.frame.judge(&shot).unwrap();
    assert!(v.legal(), "{:?}", v.foul);
}

#[test]
fn a_colour_potted_with_reds_on_is_ball_not_on_potted() {
    let (f, v) = play("ball_not_on_potted");
    assert_eq!(v.first_hit.as_deref(), Some("red1"));
    assert!(v.potted.contains(&"pink".to_string()));
    assert_eq!(foul(&v), (FoulReason::BallNotOnPotted, 6));
    assert_eq!(v.points, 0, "a red potted in a foul does not score");
    // The pink goes back on its spot.
    let n = next(&f, &v);
    let spot = spot(n.dims(), Colour::Pink);
    assert_eq!(pos_of(&n, "pink").unwrap().xy(), spot.xy());
}

#[test]
fn a_red_potted_with_a_colour_on_is_ball_not_on_potted_and_stays_down() {
    let (f, v) = play("red_potted_on_colour");
    assert_eq!(v.first_hit.as_deref(), Some("black"));
    assert_eq!(v.potted, ["red1"]);
    assert_eq!(foul(&v), (FoulReason::BallNotOnPotted, 7));
    // Reds are never respotted.
    assert!(v.respotted.is_empty());
    assert!(pos_of(&next(&f, &v), "red1").is_none());
}

#[test]
fn the_cue_ball_potted_is_a_foul_and_gives_ball_in_hand() {
    let (f, v) = play("cue_ball_potted");
    assert!(v.cue_ball_potted);
    assert_eq!(v.potted, ["pink"], "the cue ball is never listed");
    assert_eq!(foul(&v), (FoulReason::CueBallPotted, 6));
    let n = next(&f, &v);
    assert!(n.state().ball_in_hand);
    assert!(n.cue_index().is_none(), "in hand: absent from the balls");
    assert_eq!(respotted(&v), [("pink", [2.67675, 0.889])]);
}

#[test]
fn a_ball_forced_off_the_table_is_a_foul_and_goes_back_if_a_colour() {
    // A colour sent flying as the fuzz regression's ball is (scene/tests/regressions.rs): it
    // clears the top cushion. The referee sees a shot in which the cue ball hit a red and the
    // blue left the table. (A stroke of a frame file that sends a ball off: below.)
    let f = load("safety_miss");
    let strike = f.strike.unwrap();
    let mut setup = f.frame.setup(&strike).unwrap();
    let blue = setup.balls.iter().position(|b| b.id == "blue").unwrap();
    setup.balls[blue].state.pos = Vec3::new(3.3, 0.5, R);
    setup.balls[blue].state.vel = Vec3::new(0.6, 2.4, 2.9);
    setup.balls[blue].state =
        snooker_engine::motion::settle(setup.balls[blue].state, &setup.params);
    let shot = simulate(&setup, f.frame.options()).unwrap();
    assert!(
        shot.events
            .iter()
            .any(|e| e.kind == EventKind::BallOffTable)
    );
    let v = f.frame.judge(&shot).unwrap();
    assert_eq!(v.off_table, ["blue"]);
    assert_eq!(foul(&v), (FoulReason::OffTable, 5));
    assert_eq!(respotted(&v), [("blue", [1.7845, 0.889])]);
}

#[test]
fn a_power_stroke_can_send_the_cue_ball_off_the_table() {
    let (f, v) = play("cue_ball_off_table");
    assert_eq!(v.first_hit.as_deref(), Some("red1"));
    assert_eq!(v.off_table, ["cue"]);
    assert!(v.potted.is_empty());
    assert_eq!(foul(&v), (FoulReason::OffTable, 4));
    let n = next(&f, &v);
    assert!(n.state().ball_in_hand);
    assert_eq!(n.state().to_play, 1);
    assert_eq!(v.scores, [0, 4]);
}

#[test]
fn a_cue_ball_passing_over_a_ball_is_a_jump_shot() {
    // Over a ball before the first contact: a foul though the first ball hit (red2) is on.
    let (f, v) = play("jump_shot");
    assert_eq!(v.first_hit.as_deref(), Some("red2"));
    assert_eq!(foul(&v), (FoulReason::JumpShot, 4));
    assert_eq!(v.foul.as_ref().unwrap().reasons, [FoulReason::JumpShot]);
    assert_eq!(v.scores, [0, 4]);
    assert_eq!(next(&f, &v).state().to_play, 1);
    // Over the ball it struck, touching it on the way: still a jump shot.
    let (_, v) = play("jump_over_ball_struck");
    assert_eq!(v.first_hit.as_deref(), Some("red1"));
    assert_eq!(foul(&v), (FoulReason::JumpShot, 4));
    // Struck from above and landing short of its far side: no jump shot (Rule 20(b)).
    let (_, v) = play("jump_strikes_not_over");
    assert_eq!(v.first_hit.as_deref(), Some("red1"));
    assert!(v.legal(), "{:?}", v.foul);
    // The same stroke on the thesis's bed does not leave the cloth: legal, red1 first.
    let (_, v) = play("jump_bed_off");
    assert_eq!(v.first_hit.as_deref(), Some("red1"));
    assert!(v.legal(), "{:?}", v.foul);
}

#[test]
fn another_colour_potted_with_a_colour_on_is_wrong_colour_potted() {
    let (f, v) = play("wrong_colour_potted");
    assert_eq!(v.first_hit.as_deref(), Some("pink"));
    assert_eq!(v.potted, ["black"]);
    assert_eq!(foul(&v), (FoulReason::WrongColourPotted, 7));
    assert_eq!(respotted(&v), [("black", [3.245, 0.889])]);
    assert_eq!(next(&f, &v).state().on, On::Closing(Colour::Pink));
}

#[test]
fn the_colour_on_and_another_potted_is_two_colours_potted() {
    let (_, v) = play("two_colours_potted");
    assert_eq!(v.potted, ["black", "pink"]);
    assert_eq!(foul(&v), (FoulReason::TwoColoursPotted, 7));
    // Both back, the highest value first.
    assert_eq!(
        respotted(&v),
        [("black", [3.245, 0.889]), ("pink", [2.67675, 0.889])]
    );
}

#[test]
fn the_first_reason_in_the_contracts_order_names_the_foul() {
    // The cue ball hits nothing and drops: both apply, no_ball_hit comes first.
    let (_, v) = play("free_ball_not_in_hand");
    let f = v.foul.unwrap();
    assert_eq!(
        f.reasons,
        [FoulReason::NoBallHit, FoulReason::CueBallPotted]
    );
    assert_eq!(f.reason, FoulReason::NoBallHit);
}

// ---- Scoring and the ball on ----

#[test]
fn a_red_potted_scores_one_and_a_colour_is_on() {
    let (f, v) = play("pot_red");
    assert!(v.legal());
    assert_eq!((v.points, v.scores), (1, [10, 5]));
    let n = next(&f, &v);
    assert_eq!((n.state().to_play, n.state().on), (1, On::Colour));
    assert_eq!(n.state().nominated, None);
}

#[test]
fn several_reds_in_one_stroke_each_score() {
    let (_, v) = play("two_reds");
    assert!(v.legal());
    assert_eq!(v.potted.len(), 2);
    assert_eq!(v.points, 2);
}

#[test]
fn the_nominated_colour_potted_scores_its_value_and_is_respotted() {
    let (f, v) = play("pot_nominated_colour");
    assert!(v.legal());
    assert_eq!((v.points, v.scores), (7, [8, 0]));
    assert_eq!(respotted(&v), [("black", [3.245, 0.889])]);
    let n = next(&f, &v);
    assert_eq!((n.state().to_play, n.state().on), (0, On::Red));
}

#[test]
fn the_colour_after_the_last_red_is_respotted_and_the_yellow_is_on() {
    let (f, v) = play("colour_after_last_red");
    assert_eq!((v.points, v.scores), (7, [67, 12]));
    assert_eq!(respotted(&v), [("black", [3.245, 0.889])]);
    assert_eq!(next(&f, &v).state().on, On::Closing(Colour::Yellow));
}

#[test]
fn a_closing_colour_potted_stays_down_and_the_next_is_on() {
    let (f, v) = play("closing_colour");
    assert_eq!((v.points, v.scores), (2, [42, 12]));
    assert!(v.respotted.is_empty());
    let n = next(&f, &v);
    assert!(pos_of(&n, "yellow").is_none());
    assert_eq!(
        (n.state().to_play, n.state().on),
        (0, On::Closing(Colour::Green))
    );
}

#[test]
fn a_stroke_that_scores_nothing_hands_the_table_over_on_the_lowest_ball_on() {
    let (f, v) = play("safety_miss");
    assert!(v.legal());
    assert_eq!((v.points, v.scores), (0, [3, 8]));
    let n = next(&f, &v);
    assert_eq!((n.state().to_play, n.state().on), (1, On::Red));
    assert!(!n.state().free_ball, "no free ball after a legal stroke");
}

// ---- Respotting (WPBSA Section 3 Rule 7) ----

#[test]
fn a_colour_whose_spot_is_taken_goes_to_the_highest_free_spot() {
    let (_, v) = play("respot_highest_free_spot");
    assert_eq!(respotted(&v), [("black", [2.67675, 0.889])]);
}

#[test]
fn with_every_spot_taken_a_colour_goes_up_the_table_against_the_ball_in_the_way() {
    let (f, v) = play("respot_all_spots_occupied");
    let black = spot(f.frame.dims(), Colour::Black);
    let (_, at) = respotted(&v)[0];
    // 2R beyond the red on its spot, on its line.
    assert_eq!(at[1], black.y);
    assert!((at[0] - (black.x + 2.0 * R)).abs() < 1e-12, "{at:?}");
}

/// True when no point of the line from `from` to `to` (every 0.1 mm) has room for a ball among
/// `balls`, and `at` has: the respot is the nearest place with room along that line.
fn nearest_with_room(at: Vec3, from: Vec3, balls: &[Vec3]) {
    let room = |p: Vec3| {
        balls
            .iter()
            .all(|b| (b.xy() - p.xy()).norm() >= 2.0 * R * (1.0 - 1e-9))
    };
    assert!(room(at), "{at:?}");
    let d = at - from;
    let steps = (d.norm() / 1e-4) as usize;
    for k in 0..steps {
        let p = from + d * (k as f64 / steps as f64);
        assert!(!room(p), "room at {p:?} nearer than {at:?}");
    }
}

#[test]
fn the_black_with_no_room_up_the_table_goes_below_its_spot() {
    let (f, v) = play("respot_black_fallback");
    let n = next(&f, &v);
    let black = spot(n.dims(), Colour::Black);
    let (_, at) = respotted(&v)[0];
    let at = Vec3::new(at[0], at[1], 0.0);
    assert!(at.x < black.x && at.y == black.y, "{at:?}");
    let others: Vec<Vec3> = n
        .balls()
        .iter()
        .filter(|b| b.id != "black")
        .map(|b| b.state.pos)
        .collect();
    nearest_with_room(at, black, &others);
    // And no room anywhere between the spot and the top cushion.
    let top = Vec3::new(
        n.table().length - n.params().cushion_contact_distance(),
        black.y,
        0.0,
    );
    assert!(
        respot::place(Colour::Black, &others, n.dims(), n.params())
            .unwrap()
            .x
            < black.x
    );
    let room = |p: Vec3| others.iter().all(|b| (b.xy() - p.xy()).norm() >= 2.0 * R);
    assert!((0..=1000).all(|k| !room(black + (top - black) * (k as f64 / 1000.0))));
}

#[test]
fn the_pink_with_no_room_up_the_table_goes_below_its_spot() {
    let (f, v) = play("respot_pink_fallback");
    let n = next(&f, &v);
    let pink = spot(n.dims(), Colour::Pink);
    let (_, at) = respotted(&v)[0];
    let at = Vec3::new(at[0], at[1], 0.0);
    assert!(at.x < pink.x && at.y == pink.y, "{at:?}");
    let others: Vec<Vec3> = n
        .balls()
        .iter()
        .filter(|b| b.id != "pink")
        .map(|b| b.state.pos)
        .collect();
    nearest_with_room(at, pink, &others);
    assert!(
        (at.x - (pink.x - 2.0 * R)).abs() < 1e-12,
        "against the red on its spot"
    );
}

#[test]
fn several_colours_are_respotted_highest_first_each_before_the_next() {
    let (f, v) = play("respot_several");
    assert_eq!(foul(&v).0, FoulReason::TwoColoursPotted);
    let r = respotted(&v);
    // The black's spot holds a red: the black takes the pink's, the highest free.
    assert_eq!(r[0], ("black", [2.67675, 0.889]));
    // Then the pink finds its own spot taken (by the black) and every other: up the table.
    assert_eq!(r[1].0, "pink");
    let n = next(&f, &v);
    let pink = spot(n.dims(), Colour::Pink);
    let at = Vec3::new(r[1].1[0], r[1].1[1], 0.0);
    assert!(at.x > pink.x && at.y == pink.y);
    let others: Vec<Vec3> = n
        .balls()
        .iter()
        .filter(|b| b.id != "pink")
        .map(|b| b.state.pos)
        .collect();
    nearest_with_room(at, pink, &others);
}

#[test]
fn occupied_uses_the_real_ball_radius() {
    let dims = SnookerDims::default();
    let black = spot(&dims, Colour::Black);
    let near = [black + Vec3::new(0.054, 0.0, 0.0)];
    // 54 mm from the spot: free for balls of 26.2 mm radius (2R = 52.4 mm)...
    let p = Params::default();
    assert_eq!(respot::place(Colour::Black, &near, &dims, &p), Some(black));
    // ... occupied for balls of 27.5 mm (2R = 55 mm): the black goes to the pink's spot.
    let big = Params {
        ball_radius: 0.0275,
        cushion_height: 1.4 * 0.0275,
        ..p
    };
    assert_eq!(
        respot::place(Colour::Black, &near, &dims, &big),
        Some(spot(&dims, Colour::Pink))
    );
}

// ---- Free ball (WPBSA Section 3 Rule 12) ----

#[test]
fn a_foul_that_leaves_the_incoming_player_snookered_gives_a_free_ball() {
    let (f, v) = play("free_ball_awarded");
    assert_eq!(foul(&v), (FoulReason::NoBallHit, 6));
    let n = next(&f, &v);
    assert!(n.state().free_ball);
    assert_eq!(
        (n.state().to_play, n.state().on),
        (1, On::Closing(Colour::Pink))
    );
    // The incoming player may nominate the black, the only ball other than the pink.
    assert_eq!(n.legal_nominations(), [Colour::Black]);
}

#[test]
fn a_jaw_nearer_than_the_snookering_ball_leaves_no_free_ball() {
    let (f, v) = play("free_ball_not_by_a_jaw");
    assert_eq!(foul(&v), (FoulReason::NoBallHit, 6));
    let n = next(&f, &v);
    let at = |id: &str| pos_of(&n, id).unwrap();
    // The black alone hides both edges of the pink from where the cue ball stopped...
    assert!(snookered::is_snookered(
        at("cue"),
        &[at("pink")],
        &[at("black")],
        &[],
        R
    ));
    // ... but the pocket's jaw is met first on both (Section 2 Rule 17(e)): not snookered.
    let curved = snookered::curved_faces(n.table(), n.params());
    assert!(!snookered::is_snookered(
        at("cue"),
        &[at("pink")],
        &[at("black")],
        &curved,
        R
    ));
    assert!(!n.state().free_ball);
    // Without the jaws, the black nearer the cue ball than any jaw is a snooker: a ball
    // beside the cue ball on the pink's line.
    let beside = at("cue") + Vec3::new(-0.06, 0.003, 0.0);
    assert!(snookered::is_snookered(
        at("cue"),
        &[at("pink")],
        &[beside],
        &curved,
        R
    ));
}

#[test]
fn with_the_cue_ball_in_hand_there_is_a_free_ball_only_if_snookered_from_all_the_d() {
    let f = load("free_ball_not_in_hand");
    // Where the cue ball lay, the black hides the pink...
    let at = |id: &str| pos_of(&f.frame, id).unwrap();
    assert!(snookered::is_snookered(
        at("cue"),
        &[at("pink")],
        &[at("black")],
        &[],
        R
    ));
    // ... but it is potted, and from the D the pink is in view: no free ball.
    let (f, v) = play("free_ball_not_in_hand");
    let n = next(&f, &v);
    assert!(n.state().ball_in_hand);
    assert!(!n.state().free_ball);
    // A wall of balls across the table in front of the D hides a ball from all of it.
    let d = n.the_d();
    let wall: Vec<Vec3> = (0..17)
        .map(|k| Vec3::new(1.2, 0.05 + k as f64 * 0.105, R))
        .collect();
    assert!(snookered::is_snookered_in_hand(
        &d,
        &[Vec3::new(2.5, 0.9, R)],
        &wall,
        &[],
        R
    ));
    // With a gap in the middle of the wall, it is in view from the middle of the D.
    let gap: Vec<Vec3> = wall
        .iter()
        .copied()
        .filter(|w| (w.y - 0.89).abs() > 0.01)
        .collect();
    assert_eq!(gap.len(), 16);
    assert!(!snookered::is_snookered_in_hand(
        &d,
        &[Vec3::new(2.5, 0.9, R)],
        &gap,
        &[],
        R
    ));
}

#[test]
fn a_free_ball_potted_with_reds_on_counts_as_a_red_and_is_respotted() {
    let (f, v) = play("free_ball_potted");
    assert!(v.legal());
    assert_eq!((v.points, v.scores), (1, [0, 5]));
    assert_eq!(respotted(&v), [("blue", [1.7845, 0.889])]);
    let n = next(&f, &v);
    assert_eq!((n.state().to_play, n.state().on), (1, On::Colour));
    assert!(!n.state().free_ball);
}

#[test]
fn a_free_ball_that_snookers_the_ball_on_is_a_foul_but_for_pink_and_black() {
    // Section 3 Rule 12(b)(ii): the blue, played as a red, left between the cue ball and
    // every red. On the old referee this stroke was legal.
    let (f, v) = play("free_ball_snookers");
    assert_eq!(foul(&v), (FoulReason::SnookeredByFreeBall, 4));
    assert_eq!(
        v.foul.as_ref().unwrap().reasons,
        [FoulReason::SnookeredByFreeBall]
    );
    assert_eq!((v.points, v.scores), (0, [4, 4]));
    let n = next(&f, &v);
    // The opponent comes in snookered by the same blue: a free ball again.
    assert_eq!((n.state().to_play, n.state().on), (0, On::Red));
    assert!(n.state().free_ball);
    // The pink in front of the reds would snooker the cue ball without the blue too, but the
    // blue is the nearer: the effective snookering ball (Section 2 Rule 17(b)).
    let (_, v) = play("free_ball_snookers_before_the_pink");
    assert_eq!(foul(&v), (FoulReason::SnookeredByFreeBall, 4));
    // The brown beside the blue's path, nearer the cue ball: reds obstructed by different
    // balls have no effective snookering ball (Rule 17(c)): no foul, and a legal stroke gives
    // the opponent no free ball.
    let (f, v) = play("free_ball_snookers_not_its_doing");
    assert!(v.legal(), "{:?}", v.foul);
    assert!(!next(&f, &v).state().free_ball);
    // With only the pink and black left the free ball may snooker.
    let (_, v) = play("free_ball_snookers_pink_and_black");
    assert!(v.legal(), "{:?}", v.foul);
    assert_eq!((v.points, v.scores), (0, [40, 44]));
}

#[test]
fn a_touching_ball_must_not_be_moved_and_one_on_counts_as_hit() {
    // Section 3 Rule 8. Played away from a touching red, meeting nothing: the red counts as
    // hit (8(c)); the old referee called no_ball_hit.
    let (f, v) = play("touching_red_played_away");
    assert_eq!(f.frame.touching().len(), 1);
    assert!(v.legal(), "{:?}", v.foul);
    assert_eq!(
        (v.points, v.scores, v.first_hit.as_deref()),
        (0, [10, 20], None)
    );
    let n = next(&f, &v);
    assert_eq!((n.state().to_play, n.state().on), (1, On::Red));
    // Struck into it: a push stroke (8(b)); the old referee called it legal, the red hit.
    let (_, v) = play("touching_red_pushed");
    assert_eq!(foul(&v), (FoulReason::PushStroke, 4));
    assert_eq!(v.scores, [10, 24]);
    // With a free ball nominated, the touching red is not the ball to hit: played away,
    // meeting nothing, a foul (Rule 12(c)(i)); the old referee called it legal.
    let (_, v) = play("free_ball_touching_red_played_away");
    assert_eq!(foul(&v), (FoulReason::NoBallHit, 4));
    // A touching ball not on does not count as hit (8(d)).
    let (f, v) = play("touching_black_played_away");
    assert_eq!(f.frame.touching().len(), 1);
    assert_eq!(foul(&v), (FoulReason::NoBallHit, 4));
}

#[test]
fn a_free_ball_in_the_closing_sequence_scores_the_ball_on_and_it_stays_on() {
    let (f, v) = play("free_ball_closing");
    assert_eq!((v.points, v.scores), (2, [20, 26]));
    assert_eq!(respotted(&v), [("green", [0.737, 1.181])]);
    assert_eq!(next(&f, &v).state().on, On::Closing(Colour::Yellow));
}

#[test]
fn with_a_free_ball_another_ball_hit_first_is_a_foul() {
    let (_, v) = play("free_ball_wrong_first");
    assert_eq!(foul(&v), (FoulReason::FirstHitNotOn, 7));
}

#[test]
fn with_a_free_ball_nominated_the_ball_on_hit_first_is_a_foul_unless_declined() {
    // Rule 12(c)(i): the nominated free ball must be hit first (or with the ball on at once).
    let (f, v) = play("free_ball_red_first");
    assert_eq!(foul(&v), (FoulReason::FirstHitNotOn, 4));
    assert_eq!((v.points, v.scores), (0, [4, 4]));
    assert_eq!(v.potted, ["red1"]);
    // Rule 12(b): the player may nominate; nothing nominated declines the free ball, and the
    // same stroke is a red potted.
    let declined = f.frame.with_nomination(None).unwrap();
    assert!(!declined.state().free_ball);
    let setup = declined.setup(&f.strike.unwrap()).unwrap();
    let v = declined
        .judge(&simulate(&setup, declined.options()).unwrap())
        .unwrap();
    assert!(v.legal());
    assert_eq!((v.points, v.scores), (1, [0, 5]));
}

#[test]
fn in_the_closing_sequence_the_ball_on_hit_before_the_free_ball_is_a_foul_and_goes_back() {
    let (f, v) = play("free_ball_closing_on_first");
    assert_eq!(foul(&v), (FoulReason::FirstHitNotOn, 4));
    assert_eq!((v.points, v.scores), (0, [24, 24]));
    assert_eq!(respotted(&v), [("yellow", [0.737, 0.597])]);
    assert_eq!(next(&f, &v).state().on, On::Closing(Colour::Yellow));
}

// ---- End of the frame (WPBSA Section 3 Rule 4) ----

#[test]
fn the_last_black_potted_ends_the_frame() {
    let (f, v) = play("last_black");
    assert!(v.frame_over());
    assert_eq!((v.scores, v.winner), ([57, 40], Some(0)));
    assert!(v.respotted.is_empty());
    assert_eq!(
        f.frame.next(&v),
        Next::Over {
            winner: 0,
            scores: [57, 40]
        }
    );
}

#[test]
fn a_foul_on_the_last_black_ends_the_frame() {
    let (_, v) = play("last_black_foul");
    assert_eq!(foul(&v), (FoulReason::NoBallHit, 7));
    assert_eq!((v.scores, v.winner), ([50, 55], Some(1)));
    assert!(v.frame_over());
}

#[test]
fn a_tied_frame_respots_the_black_for_the_first_player_from_hand() {
    let (f, v) = play("tied_frame");
    assert_eq!(v.scores, [47, 47]);
    assert!(!v.frame_over() && v.winner.is_none());
    assert_eq!(respotted(&v), [("black", [3.245, 0.889])]);
    let n = next(&f, &v);
    let s = n.state();
    assert_eq!(
        (s.on, s.to_play, s.ball_in_hand),
        (On::Closing(Colour::Black), 1, true)
    );
    assert!(n.cue_index().is_none());
    // The next score or foul decides it: a foul by the first player (the cue ball, placed
    // in the D, sent away from the black) gives the frame to player 0, 54-47.
    let placed = n.with_cue_ball_at([0.6, 0.7]).unwrap();
    let stroke = placed
        .play(&snooker_engine::Cue {
            speed: 0.5,
            aim: std::f64::consts::PI,
            offset: [0.0, 0.0],
            elevation: 0.0,
        })
        .unwrap();
    assert_eq!(foul(&stroke.verdict), (FoulReason::NoBallHit, 7));
    assert_eq!(
        (stroke.verdict.scores, stroke.verdict.winner),
        ([54, 47], Some(0))
    );
}

#[test]
fn a_foul_on_the_last_black_that_ties_the_frame_respots_the_black() {
    let (f, v) = play("tied_by_foul");
    assert_eq!(foul(&v), (FoulReason::NoBallHit, 7));
    assert_eq!(v.scores, [50, 50]);
    assert!(!v.frame_over() && v.winner.is_none());
    assert_eq!(respotted(&v), [("black", [3.245, 0.889])]);
    let n = next(&f, &v);
    let s = n.state();
    assert_eq!(
        (s.on, s.to_play, s.ball_in_hand, s.free_ball),
        (On::Closing(Colour::Black), 0, true, false)
    );
    // Lots decide who plays the re-spotted black: the non-offender cannot ask for a play again.
    assert!(f.frame.play_again(&v).is_none());
}

// ---- After a foul: play again, a free ball declined (WPBSA Section 3 Rules 3(b), 12, 13) ----

#[test]
fn after_a_foul_the_offender_may_be_asked_to_play_again_and_the_free_ball_is_void() {
    let (f, v) = play("free_ball_awarded");
    let n = next(&f, &v);
    assert_eq!((n.state().to_play, n.state().free_ball), (1, true));
    let again = f
        .frame
        .play_again(&v)
        .expect("a foul: the offender may play again");
    let s = again.state();
    assert_eq!(
        (s.to_play, s.on, s.scores, s.ball_in_hand, s.free_ball),
        (0, On::Closing(Colour::Pink), [30, 36], false, false)
    );
    assert_eq!(again.balls(), n.balls(), "the table as the stroke left it");
    // Chained: the frame the offender plays follows from the stroke, as the next frame does.
    again.follows(&again).unwrap();
    assert!(
        again.follows(&n).is_err(),
        "not the incoming player's frame"
    );
    // The cue ball in hand: the offender plays from hand.
    let (f, v) = play("cue_ball_potted");
    let again = f.frame.play_again(&v).unwrap();
    assert_eq!(
        (again.state().to_play, again.state().ball_in_hand),
        (0, true)
    );
    assert!(again.cue_index().is_none());
    // Only after a foul that does not end the frame.
    for name in ["pot_red", "safety_miss", "last_black_foul", "tied_frame"] {
        let (f, v) = play(name);
        assert!(f.frame.play_again(&v).is_none(), "{name}");
    }
}

#[test]
fn after_a_foul_called_a_miss_the_balls_may_be_put_back_for_the_offender() {
    // Whether it was a miss is the referee's call (docs/rules.md); the frame put back is given.
    let (f, v) = play("cue_ball_potted");
    let back = f.frame.put_back(&v).expect("a foul");
    let s = back.state();
    assert_eq!(
        (s.to_play, s.on, s.scores, s.ball_in_hand),
        (0, On::Closing(Colour::Pink), [30, 36], false)
    );
    assert_eq!(back.balls(), f.frame.balls(), "the balls where they were");
    back.follows(&back).unwrap();
    assert!(back.follows(&next(&f, &v)).is_err());
    for name in ["pot_red", "safety_miss", "last_black_foul", "tied_by_foul"] {
        let (f, v) = play(name);
        assert!(f.frame.put_back(&v).is_none(), "{name}");
    }
}

#[test]
fn a_free_ball_declined_follows_from_the_stroke_before() {
    let (f, v) = play("free_ball_awarded");
    let n = next(&f, &v);
    assert!(n.state().free_ball);
    // The incoming player nominates nothing: the free ball declined, the pink played as on.
    let declined = n.with_nomination(None).unwrap();
    assert!(!declined.state().free_ball);
    declined
        .follows(&n)
        .unwrap_or_else(|e| panic!("declining a free ball is the player's choice: {e}"));
    // A free ball that was not awarded cannot be taken.
    let e = n.follows(&declined).unwrap_err();
    assert_eq!(e.key.to_string(), "frame.free_ball");
}

// ---- The cue ball in hand (WPBSA Section 3 Rule 5) ----

#[test]
fn a_cue_ball_in_hand_placed_in_the_d_is_played() {
    let (f, v) = play("in_hand_placed");
    assert!(v.legal());
    assert!(!next(&f, &v).state().ball_in_hand);
}

#[test]
fn a_placement_outside_the_d_or_touching_a_ball_is_refused() {
    let f = load("in_hand_placed").frame;
    let e = f.with_cue_ball_at([0.8, 1.0]).unwrap_err();
    assert!(
        matches!(e.problem, snooker_rules::Problem::OutsideD(_)),
        "{e}"
    );
    let brown = pos_of(&f, "brown").unwrap();
    let e = f
        .with_cue_ball_at([brown.x - 2.0 * R, brown.y])
        .unwrap_err();
    assert!(
        matches!(e.problem, snooker_rules::Problem::Touching { .. }),
        "{e}"
    );
    // The nearest valid place to a refused one is valid and close by.
    let p = f.nearest_placement([brown.x - 2.0 * R, brown.y]).unwrap();
    assert!(f.with_cue_ball_at(p).is_ok());
    assert!((p[0] - (brown.x - 2.0 * R)).abs() < 0.003);
    let _ = BallState::at_rest(p[0], p[1], R);
}
