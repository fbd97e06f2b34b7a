//! Every way off the cloth is an event (issue 21): the playing area's boundary is the cushion
//! noses and the six pocket openings, and a ball's centre leaves the region they bound only
//! by an event — a cushion, jaw or facing contact, `ball_pocket` or `ball_off_table`. Balls
//! are thrown, in the air and on the cloth, at every pocket and cushion at random, and every
//! shot is sampled every 0.5 ms and around every event (`snooker_engine::audit`): no ball in
//! play is ever off the table, and every ball ends on the cloth, in a pocket or off the table.

mod common;

use snooker_engine::impact::sweep::Rng;
use snooker_engine::sim::EventKind;
use snooker_engine::{Ball, BallKind, BallState, Models, Motion, Params, Setup, Table, Vec3};
use snooker_engine::{audit, simulate};

fn ball(id: &str, state: BallState) -> Ball {
    Ball {
        id: id.into(),
        kind: BallKind::from_id(id),
        state,
    }
}

/// A ball on the cloth near `target` (plan) on the table's side, thrown at it: in the air
/// (vertical speed up to 4 m/s) or along the cloth, at 0.3-12 m/s, with any spin.
fn thrown_at(rng: &mut Rng, target: Vec3, p: &Params, table: &Table) -> Option<BallState> {
    let r = p.ball_radius;
    for _ in 0..100 {
        let from = Vec3::new(
            target.x + rng.uniform(-0.4, 0.4),
            target.y + rng.uniform(-0.4, 0.4),
            0.0,
        );
        if table
            .placement_error(from, p.cushion_contact_distance())
            .is_some()
        {
            continue;
        }
        let aim = (target - from).normalize();
        let speed = rng.uniform(0.3, 12.0);
        let vz = if rng.uniform(0.0, 1.0) < 0.8 {
            rng.uniform(0.0, 4.0)
        } else {
            0.0
        };
        return Some(BallState {
            pos: Vec3::new(from.x, from.y, r),
            vel: Vec3::new(speed * aim.x, speed * aim.y, vz),
            spin: rng.vec(1.5 * speed / r),
            motion: Motion::Stationary,
        });
    }
    None
}

#[test]
fn every_way_off_the_cloth_is_an_event() {
    let p = Params::default();
    let table = Table::snooker(&Default::default());
    let mut rng = Rng(0x5eed_0021);
    let mut seen = std::collections::BTreeMap::<String, usize>::new();
    let mut shots = 0;
    for k in 0..2400 {
        // Targets: a pocket's mouth, a jaw, a point of a nose.
        let target = match k % 3 {
            0 => {
                let pk = &table.pockets[k / 3 % table.pockets.len()];
                let axis = (pk.centre - pk.mouth).normalize();
                pk.mouth
                    + rng.uniform(-0.02, 0.08) * axis
                    + rng.uniform(-0.06, 0.06) * Vec3::new(-axis.y, axis.x, 0.0)
            }
            1 => table.jaws[k / 3 % table.jaws.len()].centre,
            _ => {
                let c = &table.cushions[k / 3 % 6];
                c.start + rng.uniform(0.0, 1.0) * (c.end - c.start)
            }
        };
        let Some(state) = thrown_at(&mut rng, target, &p, &table) else {
            continue;
        };
        let mut balls = vec![ball("cue", state)];
        // Sometimes a red in the way, near the target, for impacts in the air.
        if k % 2 == 1 {
            let near = Vec3::new(
                target.x + rng.uniform(-0.15, 0.15),
                target.y + rng.uniform(-0.15, 0.15),
                0.0,
            );
            let clear =
                (near - Vec3::new(state.pos.x, state.pos.y, 0.0)).norm() > 2.0 * p.ball_radius;
            if clear
                && table
                    .placement_error(near, p.cushion_contact_distance())
                    .is_none()
            {
                balls.push(ball(
                    "red",
                    BallState::at_rest(near.x, near.y, p.ball_radius),
                ));
            }
        }
        let setup = Setup {
            table: table.clone(),
            params: p,
            models: Models::default(),
            balls,
        };
        let shot = simulate(&setup, &Default::default())
            .unwrap_or_else(|e| panic!("shot {k}: {e}\n{:?}", setup.balls));
        shots += 1;
        if let Some(broken) = audit::report(&audit::audit(&setup, &shot)) {
            panic!("shot {k}: {broken}\n{:?}", setup.balls);
        }
        for e in &shot.events {
            let airborne = e.before.iter().any(|s| s.motion == Motion::Airborne);
            let feature = e.feature.as_deref().unwrap_or("");
            let class = match e.kind {
                EventKind::BallPocket if airborne => "pocketed from the air",
                EventKind::BallPocket => "pocketed from the cloth",
                EventKind::BallOffTable if feature.ends_with("/back") => "over a pocket's back",
                EventKind::BallOffTable if feature.ends_with(" jaw") => "over a jaw",
                EventKind::BallOffTable if feature.ends_with(" facing") => "over a facing",
                EventKind::BallOffTable => "over a nose",
                EventKind::BallCushion if airborne && feature.ends_with(" jaw") => {
                    "a jaw met in the air"
                }
                EventKind::BallCushion if airborne => "a nose or facing met in the air",
                _ => continue,
            };
            *seen.entry(class.into()).or_default() += 1;
        }
    }
    println!("{shots} shots: {seen:?}");
    for class in [
        "pocketed from the air",
        "pocketed from the cloth",
        "over a pocket's back",
        "over a jaw",
        "over a facing",
        "over a nose",
        "a jaw met in the air",
        "a nose or facing met in the air",
    ] {
        assert!(
            seen.get(class).is_some_and(|&n| n > 0),
            "no {class}: {seen:?}"
        );
    }
}

#[test]
fn a_ball_jumping_along_a_cushion_from_anywhere_on_its_line_meets_the_nose() {
    // Balls frozen to a side cushion's line (at its nose, or across a pocket's mouth, where
    // the line runs on with no nose), jumping and drifting along and into it: found by the
    // 10^6 fuzz run (seed 20261128), the touch of the edge line beyond a nose's end hid the
    // real touch of the nose further on.
    let p = Params::default();
    let table = Table::snooker(&Default::default());
    let contact = p.cushion_contact_distance();
    let mut rng = Rng(0x5eed_0022);
    let mut met = 0;
    for k in 0..1200 {
        let (x, side) = (rng.uniform(0.1, table.length - 0.1), k % 2);
        let y = if side == 0 {
            contact
        } else {
            table.width - contact
        };
        let pos = Vec3::new(x, y, 0.0);
        if table.placement_error(pos, contact).is_some() {
            continue;
        }
        let into = if side == 0 { -1.0 } else { 1.0 };
        let state = BallState {
            pos: Vec3::new(x, y, p.ball_radius),
            vel: Vec3::new(
                rng.uniform(-2.0, 2.0),
                into * rng.uniform(0.0, 0.1),
                rng.uniform(0.5, 3.0),
            ),
            spin: rng.vec(50.0),
            motion: Motion::Stationary,
        };
        let setup = Setup {
            table: table.clone(),
            params: p,
            models: Models::default(),
            balls: vec![ball("cue", state)],
        };
        let shot = simulate(&setup, &Default::default())
            .unwrap_or_else(|e| panic!("shot {k}: {e}\n{:?}", setup.balls));
        if let Some(broken) = audit::report(&audit::audit(&setup, &shot)) {
            panic!("shot {k}: {broken}\n{:?}", setup.balls);
        }
        met += shot
            .events
            .iter()
            .filter(|e| e.kind == EventKind::BallCushion && e.before[0].motion == Motion::Airborne)
            .count()
            .min(1);
    }
    assert!(met > 300, "{met}");
}

#[test]
fn the_audit_refuses_a_ball_left_off_the_cloth() {
    // A ball at rest where no ball can be, still in play: the position check refuses it (the
    // engine never leaves one there; this is the audit's own test).
    let p = Params::default();
    let table = Table::snooker(&Default::default());
    let setup = Setup {
        table: table.clone(),
        params: p,
        models: Models::default(),
        balls: vec![ball("cue", BallState::at_rest(1.0, 0.5, p.ball_radius))],
    };
    let mut shot = simulate(&setup, &Default::default()).unwrap();
    assert!(audit::positions(&table, &shot).is_empty());
    for (x, y) in [(722.8, -710.3), (-2.97, 0.3), (1.0, -0.01), (3.6, 1.0)] {
        shot.tracks[0].segments[0].state.pos = Vec3::new(x, y, p.ball_radius);
        let broken = audit::positions(&table, &shot);
        assert_eq!(broken.len(), 1, "({x}, {y}): {broken:?}");
        assert!(
            matches!(broken[0], audit::Violation::OffTable { .. }),
            "{broken:?}"
        );
        assert!(!audit::audit(&setup, &shot).is_empty());
    }
    // Resting in a pocket's jaws, or pocketed anywhere, is not off the table.
    let jaw = &table.pockets[0];
    shot.tracks[0].segments[0].state.pos = jaw.mouth + Vec3::new(0.0, 0.0, p.ball_radius);
    assert!(audit::positions(&table, &shot).is_empty());
    shot.tracks[0].segments[0].state.pos = Vec3::new(-5.0, -5.0, p.ball_radius);
    shot.tracks[0].segments[0].state.motion = Motion::Pocketed;
    assert!(audit::positions(&table, &shot).is_empty());
}

/// Issue 21, fuzz seed 20261128 (10^6 scenes, all 8 failures): the placement rule took a
/// centre a few cm behind a corner, past the fall, for a ball "in the pocket's mouth" (within
/// the mouth's width of its middle, clear of the noses and facings), though the hole lies
/// between it and the table. Struck away from the table it never crosses the fall, meets no
/// nose or facing, and runs off the end of the world unnoticed (the audit's "off the table
/// ... still in play"). Behind the fall's diameter across the pocket's axis is the pocket's
/// back, where no ball can rest: such a scene is refused, like any centre off the cloth.
#[test]
fn a_ball_behind_a_corner_fall_is_off_the_cloth_not_in_the_mouth() {
    let p = Params::default();
    let table = Table::snooker(&Default::default());
    let contact = p.cushion_contact_distance();
    // (position, velocity) of the placed ball in scenes 935315 (red11, baulk-right corner),
    // 595804 (red13, top-right) and 751635 (red11, top-left, thrown up).
    let scenes = [
        (
            [-0.034_389_803_864_360_23, -0.029_028_059_245_823_974],
            [-13.98, 12.19, 0.0],
        ),
        (
            [3.596_658_291_292_957, -0.035_504_671_901_194_52],
            [0.868, -2.097, 0.0],
        ),
        (
            [3.604_684_911_157_489_7, 1.805_459_689_786_929_3],
            [2.32, 3.58, 3.05],
        ),
    ];
    for (pos, vel) in scenes {
        let at = Vec3::new(pos[0], pos[1], 0.0);
        assert!(
            table.placement_error(at, contact).is_some(),
            "{pos:?} accepted behind the fall"
        );
        let mut state = BallState::at_rest(pos[0], pos[1], p.ball_radius);
        state.vel = Vec3::new(vel[0], vel[1], vel[2]);
        let setup = Setup {
            table: table.clone(),
            params: p,
            models: Models::default(),
            balls: vec![ball("red", state)],
        };
        assert!(setup.validate().is_err(), "{pos:?}: the scene validates");
    }
}

/// The placement rule and the audit agree: every centre where a ball may be placed at rest
/// (`Table::placement_error`) is one the audit holds on the table (`audit::on_table`), on a
/// 1 mm grid over every pocket's opening and its surround.
#[test]
fn every_placeable_centre_is_on_the_table_for_the_audit() {
    let p = Params::default();
    let table = Table::snooker(&Default::default());
    let contact = p.cushion_contact_distance();
    let mut placeable = 0;
    for pk in &table.pockets {
        for i in -120..=120 {
            for j in -120..=120 {
                let at = pk.mouth + Vec3::new(i as f64 * 1e-3, j as f64 * 1e-3, 0.0);
                if table.placement_error(at, contact).is_some() {
                    continue;
                }
                placeable += 1;
                let s = BallState::at_rest(at.x, at.y, p.ball_radius);
                assert!(
                    audit::on_table(&table, &p, &s),
                    "({:.4}, {:.4}) near {} placeable but off the table for the audit",
                    at.x,
                    at.y,
                    pk.name
                );
            }
        }
    }
    assert!(placeable > 1000, "{placeable}");
}

/// Fuzz scene 420183 (seed 20261128), its one ball: a red thrown up from mid-table comes down
/// onto the top-right pocket's top jaw 0.62 s later. The jaw contact's root, taken from a
/// polynomial expanded about the throw, was ~1e-7 m off and refused, so the red landed on the
/// cushion's body behind the jaw and rolled away to (149, -356) m. It now meets the jaw (or
/// leaves the table by an event) and the audit finds no ball off the cloth.
#[test]
fn a_red_thrown_onto_a_far_jaw_meets_it() {
    let p = Params::default();
    let table = Table::snooker(&Default::default());
    let mut state = BallState::at_rest(
        0.897_861_608_416_986,
        0.304_817_902_073_025_06,
        p.ball_radius,
    );
    state.vel = Vec3::new(
        4.252_456_216_072_619,
        -0.395_041_506_300_891_47,
        3.105_753_587_054_569_4,
    );
    state.spin = Vec3::new(
        1_149.743_515_812_419_4,
        50.707_100_702_406_47,
        907.196_996_290_052_5,
    );
    let setup = Setup {
        table: table.clone(),
        params: p,
        models: Models::default(),
        balls: vec![ball("red10", state)],
    };
    setup.validate().unwrap();
    let shot = simulate(&setup, &Default::default()).unwrap();
    let first = shot.events.first().expect("an event");
    assert_eq!(
        first.kind,
        EventKind::BallCushion,
        "{:?} at {}",
        first.kind,
        first.t
    );
    assert_eq!(first.feature.as_deref(), Some("top-right/top jaw"));
    assert!((0.62..0.627).contains(&first.t), "{}", first.t);
    assert!(audit::positions(&table, &shot).is_empty());
    let end = shot.final_states()[0];
    assert!(
        !end.motion.in_play() || audit::on_table(&table, &p, &end),
        "{:?} at {:?}",
        end.motion,
        end.pos
    );
}
