//! What the pot examples share: a cue ball and one red on an empty table, the cue ball placed
//! at a cut and a distance from the red's contact for a pot in the top-left pocket, as a
//! planner problem.
use snooker_engine::{
    Ball, BallKind, BallState, Models, Params, Setup, SimOptions, SnookerDims, Table, Vec3,
};
use snooker_planner::{Problem, Request};

/// The table and its top-left pocket's mouth.
pub fn table() -> (Table, Vec3) {
    let table = Table::snooker(&SnookerDims::default());
    let mouth = table
        .pockets
        .iter()
        .find(|k| k.name == "top-left")
        .expect("a snooker table has a top-left pocket")
        .mouth;
    (table, mouth)
}

/// Where the cue ball lies `d` m back from the red's contact (its ghost ball) at a cut of
/// `cut_deg` degrees for a pot of the red at `red` into the mouth `mouth`.
pub fn cue_at(red: Vec3, mouth: Vec3, cut_deg: f64, d: f64, r: f64) -> Vec3 {
    let u = (mouth - red).normalize();
    let u = Vec3::new(u.x, u.y, 0.0);
    let c = cut_deg.to_radians();
    let ghost = red - 2.0 * r * u;
    let back = Vec3::new(
        u.x * c.cos() - u.y * c.sin(),
        u.x * c.sin() + u.y * c.cos(),
        0.0,
    );
    ghost - d * back
}

/// The planner's problem of potting the red at `red` in the top-left pocket from `cue`, the
/// cue ball's target where it lies, one sample per plan.
pub fn problem(table: &Table, p: &Params, cue: Vec3, red: Vec3) -> Option<Problem> {
    let r = p.ball_radius;
    let balls = vec![
        Ball {
            id: "cue".into(),
            kind: BallKind::Cue,
            state: BallState::at_rest(cue.x, cue.y, r),
        },
        Ball {
            id: "red".into(),
            kind: BallKind::Red,
            state: BallState::at_rest(red.x, red.y, r),
        },
    ];
    let setup = Setup {
        table: table.clone(),
        params: *p,
        models: Models::default(),
        balls,
    };
    let mut req = Request::new("red", "top-left", [cue.x, cue.y], p);
    req.samples = 1;
    Problem::for_setup(setup, SimOptions::default(), req).ok()
}

/// The share of `n` strikes `cue` executed under `noise` (draws seeded from 3 and the sample's
/// number) that pot along `line`.
pub fn pot_share(
    pr: &Problem,
    line: &snooker_planner::Line,
    cue: &snooker_engine::Cue,
    noise: &snooker_planner::Noise,
    n: u64,
) -> f64 {
    let p = pr.setup().params;
    let pots = (0..n)
        .filter(|&k| {
            let ex = noise.apply(
                cue,
                &pr.setup().balls[0].state,
                &p,
                &mut snooker_planner::rng_for(3, &[k]),
            );
            pr.trial(&ex, line).is_some_and(|x| x.pots())
        })
        .count();
    pots as f64 / n as f64
}
