//! The ways a ball can be sent into a pocket, and the geometry that first aims each: a direct
//! pot (cue ball -> object ball -> pocket), a double (the object ball off one or two cushions),
//! a plant (cue ball -> ball A -> object ball -> pocket) and a kiss (the object ball glancing
//! off another ball into the pocket). The geometry is the ghost-ball construction with cushions
//! as mirrors and frictionless collisions; the engine's result then corrects the heading
//! ([`crate::aim`]), so throw, squirt, swerve and the cushions' real rebound angles are
//! allowed for by the simulation itself.

use crate::problem::Problem;
use snooker_engine::{Params, Vec3};

/// The kind of a potting shot.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ShotKind {
    /// Cue ball -> object ball -> pocket.
    Direct,
    /// The object ball off one or two cushions into the pocket.
    Double,
    /// Cue ball -> another ball -> the object ball -> pocket.
    Plant,
    /// The object ball glances off another ball into the pocket.
    Kiss,
}

impl ShotKind {
    /// Its name (`direct`, `double`, `plant`, `kiss`).
    pub fn name(self) -> &'static str {
        match self {
            ShotKind::Direct => "direct",
            ShotKind::Double => "double",
            ShotKind::Plant => "plant",
            ShotKind::Kiss => "kiss",
        }
    }

    /// The kind of this [`ShotKind::name`], if any.
    pub fn from_name(name: &str) -> Option<ShotKind> {
        ShotKind::ALL.into_iter().find(|k| k.name() == name)
    }

    /// All of them, in the order the planner tries them.
    pub const ALL: [ShotKind; 4] = [
        ShotKind::Direct,
        ShotKind::Double,
        ShotKind::Plant,
        ShotKind::Kiss,
    ];
}

/// One way of potting the object ball: its kind and the balls or cushions it uses.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Line {
    /// The kind.
    pub kind: ShotKind,
    /// For a plant the ball struck first, for a kiss the ball kissed (indices into the
    /// setup's balls); none otherwise.
    pub ball: Option<usize>,
    /// For a double, the cushions the object ball meets in order (indices into the table's
    /// cushions, noses only).
    pub cushions: Vec<usize>,
    /// Which of the kiss's geometric solutions (there may be two).
    pub branch: u8,
}

impl Line {
    /// The direct pot.
    pub fn direct() -> Line {
        Line {
            kind: ShotKind::Direct,
            ball: None,
            cushions: Vec::new(),
            branch: 0,
        }
    }
}

/// Most cut, rad, at which a line's contacts are still aimed (thinner cuts are left out: the
/// object ball then barely moves and the aim is hopeless).
const MAX_CUT: f64 = 80.0 * std::f64::consts::PI / 180.0;
/// Most cut of a plant's second contact, rad (a plant's error grows as 1/cos of it).
const MAX_PLANT_CUT: f64 = 70.0 * std::f64::consts::PI / 180.0;
/// Largest gap between two balls that makes them a set for a plant, m: within it the
/// ghost-ball geometry degenerates and the object ball leaves along the line of centres
/// (a review found touching balls, and a 0.1 mm gap, refused; 1 mm was planned as usual).
pub const SET_GAP: f64 = 1e-3;
/// A double's cushion contact must lie this far (m) inside the cushion's nose segment.
const CUSHION_MARGIN: f64 = 0.01;

fn unit(v: Vec3) -> Vec3 {
    let n = v.xy().norm();
    if n > 0.0 {
        Vec3::new(v.x / n, v.y / n, 0.0)
    } else {
        Vec3::zeros()
    }
}

/// Where the centre of a ball at `b` must be to send it to `to`: two radii behind it.
pub fn ghost(b: Vec3, to: Vec3, r: f64) -> Vec3 {
    b - 2.0 * r * unit(to - b)
}

/// The cut (rad, 0 full ball) of a ball arriving from `from` at the ghost `g` of a ball at `b`.
fn cut(from: Vec3, g: Vec3, b: Vec3) -> f64 {
    let (u, w) = (unit(g - from), unit(b - g));
    (u.x * w.y - u.y * w.x).atan2(u.dot(&w)).abs()
}

impl Problem {
    /// True when a ball moving from `a` to `b` passes clear of every ball in play but those
    /// listed (centres more than two radii from the segment).
    pub fn clear(&self, a: Vec3, b: Vec3, except: &[usize]) -> bool {
        let r = self.setup.params.ball_radius;
        let d = (b - a).xy();
        let len2 = d.norm_squared();
        self.setup.balls.iter().enumerate().all(|(i, ball)| {
            if except.contains(&i) || !ball.state.motion.in_play() {
                return true;
            }
            let p = (ball.state.pos - a).xy();
            let s = if len2 > 0.0 {
                (p.dot(&d) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (p - s * d).norm() >= 2.0 * r
        })
    }

    fn pos(&self, i: usize) -> Vec3 {
        let p = self.setup.balls[i].state.pos;
        Vec3::new(p.x, p.y, 0.0)
    }

    /// The line of ball centres touching cushion `c`: a point on it and its unit normal
    /// (into the table).
    fn centre_line(&self, c: usize) -> (Vec3, Vec3) {
        let cushion = &self.setup.table.cushions[c];
        let d = self.setup.params.cushion_contact_distance();
        (cushion.start + d * cushion.normal, cushion.normal)
    }

    /// Where a ball moving from `a` towards `b` meets the centre line of cushion `c`, if it
    /// meets it head on within the nose segment.
    fn cushion_hit(&self, c: usize, a: Vec3, b: Vec3) -> Option<Vec3> {
        let (p0, n) = self.centre_line(c);
        let (da, db) = ((a - p0).dot(&n), (b - p0).dot(&n));
        if da <= 0.0 || db >= 0.0 {
            return None;
        }
        let hit = a + (da / (da - db)) * (b - a);
        let cushion = &self.setup.table.cushions[c];
        let along = (hit - cushion.start).dot(&cushion.direction());
        (along > CUSHION_MARGIN && along < cushion.length() - CUSHION_MARGIN).then_some(hit)
    }

    /// Mirror image of `q` in the centre line of cushion `c`.
    fn mirror(&self, c: usize, q: Vec3) -> Vec3 {
        let (p0, n) = self.centre_line(c);
        q - 2.0 * (q - p0).dot(&n) * n
    }

    /// The noses (straight cushions that are not pocket facings).
    fn noses(&self) -> Vec<usize> {
        (0..self.setup.table.cushions.len())
            .filter(|&c| !self.setup.table.cushions[c].name.contains("facing"))
            .collect()
    }

    /// The points the object ball's path turns at on the way to `at` along a double, in
    /// order (the cushion contacts), if the geometry allows it.
    fn double_path(&self, cushions: &[usize], at: Vec3) -> Option<Vec<Vec3>> {
        let o = self.pos(self.object);
        let mut image = at;
        for &c in cushions.iter().rev() {
            image = self.mirror(c, image);
        }
        let mut from = o;
        let mut points = Vec::new();
        for (k, &c) in cushions.iter().enumerate() {
            let hit = self.cushion_hit(c, from, image)?;
            points.push(hit);
            from = hit;
            // The remaining images unfold one cushion at a time.
            image = at;
            for &c2 in cushions[k + 1..].iter().rev() {
                image = self.mirror(c2, image);
            }
        }
        Some(points)
    }

    /// The kiss contact: where the object ball's centre must be when it meets ball `x` so
    /// that it glances off towards `at` (frictionless, restitution `e_ball`), solution
    /// `branch` (0 or 1) of those found.
    fn kiss_contact(&self, x: usize, at: Vec3, branch: u8) -> Option<Vec3> {
        let p: &Params = &self.setup.params;
        let r = p.ball_radius;
        let beta = 0.5 * (1.0 + p.e_ball);
        let (o, xc) = (self.pos(self.object), self.pos(x));
        let f = |theta: f64| -> Option<(f64, f64)> {
            let n = Vec3::new(theta.cos(), theta.sin(), 0.0);
            let k = xc - 2.0 * r * n;
            let v = unit(k - o);
            let vn = v.dot(&n);
            if (k - o).xy().norm() < 1e-9 || vn < 0.15 {
                return None;
            }
            let w = v - beta * vn * n;
            let to = unit(at - k);
            Some((w.x * to.y - w.y * to.x, w.dot(&to)))
        };
        const STEPS: usize = 144;
        let mut found = Vec::new();
        let mut prev: Option<(f64, f64, f64)> = None;
        for s in 0..=STEPS {
            let theta = s as f64 * std::f64::consts::TAU / STEPS as f64;
            match f(theta) {
                Some((c, d)) => {
                    if let Some((t0, c0, _)) = prev
                        && c0.signum() != c.signum()
                        && d > 0.0
                    {
                        // Bisection on the sign change.
                        let (mut lo, mut hi, mut clo) = (t0, theta, c0);
                        for _ in 0..50 {
                            let mid = 0.5 * (lo + hi);
                            match f(mid) {
                                Some((cm, _)) if cm.signum() == clo.signum() => {
                                    lo = mid;
                                    clo = cm;
                                }
                                Some(_) => hi = mid,
                                None => break,
                            }
                        }
                        let theta = 0.5 * (lo + hi);
                        if let Some((_, d)) = f(theta)
                            && d > 0.0
                        {
                            found.push(xc - 2.0 * r * Vec3::new(theta.cos(), theta.sin(), 0.0));
                        }
                    }
                    prev = Some((theta, c, d));
                }
                None => prev = None,
            }
        }
        found.get(branch as usize).copied()
    }

    /// The first heading of the cue for `line` with the object ball's last leg aimed at `at`
    /// (rad), and the cut on the ball the cue ball strikes; None when the geometry does not
    /// allow the line.
    pub fn line_aim(&self, line: &Line, at: Vec3) -> Option<(f64, f64)> {
        let r = self.setup.params.ball_radius;
        let c = self.pos(self.cue);
        let o = self.pos(self.object);
        let heading = |g: Vec3| {
            let d = g - c;
            d.y.atan2(d.x)
        };
        match line.kind {
            ShotKind::Direct => {
                let g = ghost(o, at, r);
                Some((heading(g), cut(c, g, o)))
            }
            ShotKind::Double => {
                let first = *self.double_path(&line.cushions, at)?.first()?;
                let g = ghost(o, first, r);
                Some((heading(g), cut(c, g, o)))
            }
            ShotKind::Plant => {
                let a = self.pos(line.ball?);
                let (ga, _) = self.plant_geometry(a, o, at);
                Some((heading(ga), cut(c, ga, a)))
            }
            ShotKind::Kiss => {
                let k = self.kiss_contact(line.ball?, at, line.branch)?;
                let g = ghost(o, k, r);
                Some((heading(g), cut(c, g, o)))
            }
        }
    }

    /// Where the cue ball meets ball `a` (its ghost) to plant the object ball at `o` into the
    /// pocket's `at`, and the cut of the second contact: the ghost-ball geometry (`a` sent to
    /// the object ball's ghost). Two balls touching, or all but ([`SET_GAP`]), are a set: the
    /// ghost geometry degenerates (the object ball's ghost lies in `a`, the second cut comes
    /// out near 90 degrees and the plant was dropped before any shot was tried), while the
    /// object ball leaves along the line of centres whatever way `a` is pushed. A set whose
    /// line of centres carries the object ball's centre within the mouth (half its width less
    /// a radius of its middle) is planted by sending `a` straight at the object ball, its
    /// second cut the angle between that line and the pocket.
    fn plant_geometry(&self, a: Vec3, o: Vec3, at: Vec3) -> (Vec3, f64) {
        let r = self.setup.params.ball_radius;
        let go = ghost(o, at, r);
        let ghosted = (ghost(a, go, r), cut(a, go, o));
        if ghosted.1 < MAX_PLANT_CUT || (o - a).norm() > 2.0 * r + SET_GAP {
            return ghosted;
        }
        let along = unit(o - a);
        let to_pocket = at - o;
        let off = (along.x * to_pocket.y - along.y * to_pocket.x).abs();
        let mouth = self.setup.table.pockets[self.pocket].mouth_width;
        if along.dot(&to_pocket) <= 0.0 || off > 0.5 * mouth - r {
            return ghosted;
        }
        let second = (along.x * to_pocket.y - along.y * to_pocket.x)
            .atan2(along.dot(&to_pocket))
            .abs();
        (ghost(a, o, r), second)
    }

    /// Every line of the object ball into the pocket whose geometry is open (paths clear of
    /// other balls, cuts within reach), direct first, then doubles, plants and kisses, aimed
    /// at the middle of the mouth.
    pub fn lines(&self) -> Vec<Line> {
        let r = self.setup.params.ball_radius;
        let at = self.aim_point(0.0);
        let (c, o) = (self.pos(self.cue), self.pos(self.object));
        let (ci, oi) = (self.cue, self.object);
        let mut out = Vec::new();
        // Direct.
        {
            let g = ghost(o, at, r);
            if cut(c, g, o) < MAX_CUT && self.clear(c, g, &[ci, oi]) && self.clear(o, at, &[oi]) {
                out.push(Line::direct());
            }
        }
        // Doubles: one cushion, then two.
        let noses = self.noses();
        let mut seqs: Vec<Vec<usize>> = noses.iter().map(|&a| vec![a]).collect();
        for &a in &noses {
            for &b in &noses {
                if a != b {
                    seqs.push(vec![a, b]);
                }
            }
        }
        for cushions in seqs {
            let Some(points) = self.double_path(&cushions, at) else {
                continue;
            };
            let g = ghost(o, points[0], r);
            let mut ok = cut(c, g, o) < MAX_CUT && self.clear(c, g, &[ci, oi]);
            let mut from = o;
            for &p in points.iter().chain(std::iter::once(&at)) {
                ok = ok && self.clear(from, p, &[ci, oi]);
                from = p;
            }
            if ok {
                out.push(Line {
                    kind: ShotKind::Double,
                    ball: None,
                    cushions,
                    branch: 0,
                });
            }
        }
        let others: Vec<usize> = (0..self.setup.balls.len())
            .filter(|&i| i != ci && i != oi && self.setup.balls[i].state.motion.in_play())
            .collect();
        // Plants.
        for &ai in &others {
            let a = self.pos(ai);
            let go = ghost(o, at, r);
            let (ga, second) = self.plant_geometry(a, o, at);
            if cut(c, ga, a) < MAX_CUT
                && second < MAX_PLANT_CUT
                && self.clear(c, ga, &[ci, ai])
                && self.clear(a, go, &[ai, oi])
                && self.clear(o, at, &[oi])
            {
                out.push(Line {
                    kind: ShotKind::Plant,
                    ball: Some(ai),
                    cushions: Vec::new(),
                    branch: 0,
                });
            }
        }
        // Kisses.
        for &xi in &others {
            for branch in 0..2u8 {
                let Some(k) = self.kiss_contact(xi, at, branch) else {
                    break;
                };
                let g = ghost(o, k, r);
                if cut(c, g, o) < MAX_CUT
                    && self.clear(c, g, &[ci, oi])
                    && self.clear(o, k, &[oi, xi])
                    && self.clear(k, at, &[oi, xi])
                {
                    out.push(Line {
                        kind: ShotKind::Kiss,
                        ball: Some(xi),
                        cushions: Vec::new(),
                        branch,
                    });
                }
            }
        }
        out
    }
}
