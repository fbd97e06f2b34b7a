//! The two root searches every detector reduces to:
//! - a point (one centre relative to another, or to a circle's centre) entering a sphere or
//!   circle of radius rho: |d(t)|^2 - rho^2 = 0, a quartic in t;
//! - a point reaching a line at a given distance: a quadratic in t.
//!
//! Roots within the window are isolated by the critical points of the polynomial and refined
//! by Yuksel's safeguarded Newton method (the `polycool` crate), so a degree that collapses
//! (equal accelerations, a body at rest) needs no special formula and no division by a
//! vanishing leading coefficient. A root counts only if the bodies approach there and the
//! distance checks out.

use super::{ROOT_TIME_TOL, SKIN, TOUCH_TOL, VERIFY_TOL};
use crate::ball::Vec3;
use crate::motion::Path;
use polycool::{Poly, Quadratic};

/// Longest span searched in one go, s.
pub const MAX_WINDOW: f64 = 1e6;

/// The first time in [0, window] at which the relative path `rel` enters the sphere of radius
/// `rho` (less the [`SKIN`]) around the origin while approaching it. A path already touching
/// (within [`TOUCH_TOL`]) and approaching gives 0; one touching and at rest or separating does not.
pub fn first_entry(rel: &Path, rho: f64, window: f64) -> Option<f64> {
    entries(rel, rho, window).next()
}

/// Every time in [0, window], in order, at which the relative path `rel` enters the sphere of
/// radius `rho` while approaching it, as [`first_entry`] finds the first. A path touching now
/// gives 0 first; the later entries are searched only if they are asked for (a caller may
/// refuse the first, as a nose edge's does where the touch is beyond the nose's end).
pub fn entries(rel: &Path, rho: f64, window: f64) -> impl Iterator<Item = f64> + '_ {
    let (b, c) = (rel.b, rel.c);
    let dist0 = c.norm();
    let now = dist0 <= rho + TOUCH_TOL
        && (c.dot(&b) < 0.0
            || sphere_gap_taylor(rel, rho).is_some_and(|(g, s, q)| pressed_back(g, s, q)));
    let rho = rho - SKIN;
    let later = std::iter::once(()).flat_map(move |()| {
        let searched = !(window.is_nan()
            || window <= 0.0
            || dist0 - rho > rel.reach(window)
            || never_within(rel, rho, window.min(MAX_WINDOW)));
        let roots = if searched {
            // A law that never ends (no friction) is searched over a bounded, still
            // astronomical, span.
            sphere_quartic(rel, rho).roots_between(0.0, window.min(MAX_WINDOW), ROOT_TIME_TOL)
        } else {
            Default::default()
        };
        roots
            .into_iter()
            .map(move |t| polished(|t| sphere_gap(rel, rho, t), t, window.min(MAX_WINDOW)))
            .filter(move |&t| {
                let d = rel.at(t);
                d.dot(&rel.velocity(t)) < 0.0 && (d.norm() - rho).abs() <= VERIFY_TOL
            })
    });
    now.then_some(0.0).into_iter().chain(later)
}

/// True when a pair touching now (its gap, the distance less the contact distance, at most
/// [`TOUCH_TOL`]) but not approaching is pressed back before it ever leaves the touching band:
/// the gap grows at `rate` >= 0 but curves back (`curvature` < 0) and peaks
/// rate^2 / (2 |curvature|) further out (its Taylor expansion at 0), within the band. Such a
/// pair never parts: it is a contact now. A contact found one skin inside and then left
/// parting at a crawl (a chain of same-instant pushes: a ball squeezed between a cushion and
/// another ball, whose last push undid most of the pair's separation) would otherwise leave
/// and re-enter the search sphere by less than a rounding error of the polynomial's
/// coefficients, 1e-19 m in fuzz scene 608350 of seed 20261130, and sink in unseen.
fn pressed_back(gap: f64, rate: f64, curvature: f64) -> bool {
    rate >= 0.0 && curvature < 0.0 && gap + rate * rate / (2.0 * -curvature) <= TOUCH_TOL
}

/// The distance of the path `rel` from the origin less `rho` at 0, its rate and its second
/// derivative (the path's acceleration is 2a): the gap [`pressed_back`] judges.
fn sphere_gap_taylor(rel: &Path, rho: f64) -> Option<(f64, f64, f64)> {
    let (a, b, c) = (rel.a, rel.b, rel.c);
    let dist = c.norm();
    (dist > 0.0).then(|| {
        let s = c.dot(&b) / dist;
        (dist - rho, s, (b.dot(&b) + 2.0 * a.dot(&c) - s * s) / dist)
    })
}

/// |rel(t)|^2 - rho^2 as a quartic in t: zero where the path crosses the sphere of radius
/// `rho` around the origin.
fn sphere_quartic(rel: &Path, rho: f64) -> Poly<5> {
    let (a, b, c) = (rel.a, rel.b, rel.c);
    Poly::new([
        c.dot(&c) - rho * rho,
        2.0 * b.dot(&c),
        b.dot(&b) + 2.0 * a.dot(&c),
        2.0 * a.dot(&b),
        a.dot(&a),
    ])
}

/// Every time in [0, window], in order, at which the relative path `rel` leaves the sphere of
/// radius `rho` around the origin (moving away from it): the crossings [`entries`] leaves out.
pub fn exits(rel: &Path, rho: f64, window: f64) -> impl Iterator<Item = f64> + '_ {
    let c = rel.c;
    let searched = !(window.is_nan()
        || window <= 0.0
        || rho - c.norm() > rel.reach(window)
        || never_within(rel, rho, window.min(MAX_WINDOW)));
    let roots = if searched {
        sphere_quartic(rel, rho).roots_between(0.0, window.min(MAX_WINDOW), ROOT_TIME_TOL)
    } else {
        Default::default()
    };
    let end = window.min(MAX_WINDOW);
    roots
        .into_iter()
        .map(move |t| polished(|t| sphere_gap(rel, rho, t), t, end))
        .filter(move |&t| {
            let d = rel.at(t);
            d.dot(&rel.velocity(t)) > 0.0 && (d.norm() - rho).abs() <= VERIFY_TOL
        })
}

/// The distance of `rel` from the origin less `rho` at time `t`, and its rate.
fn sphere_gap(rel: &Path, rho: f64, t: f64) -> (f64, f64) {
    let d = rel.at(t);
    let n = d.norm();
    let rate = if n > 0.0 {
        d.dot(&rel.velocity(t)) / n
    } else {
        0.0
    };
    (n - rho, rate)
}

/// True when the path `rel` provably stays farther than `rho` from the origin over [0, `window`]
/// by more than any root could be off ([`VERIFY_TOL`]) and any rounding in the bound: no root
/// could be accepted there, so the search is skipped and nothing else changes.
fn never_within(rel: &Path, rho: f64, window: f64) -> bool {
    rel.clearance(window) - rho > CULL_MARGIN + 1e-9 * rel.size(window)
}

/// Slack of [`never_within`]'s bound beyond the distance test's tolerance, m.
const CULL_MARGIN: f64 = 1e3 * VERIFY_TOL;

/// Every time in [0, window], in order, at which a point on the path `plan` (relative to a
/// ring's centre, in plan) at height `dz` above the ring's plane (a quadratic in time, given
/// as its value, rate and half acceleration) comes within `rho` (less the [`SKIN`]) of the
/// ring of radius `ring` while approaching it: the ball touching the rounded edge of a jaw.
/// With d the plan distance from the axis, (d - ring)^2 + dz^2 = rho^2 squares to an
/// octic in time; its roots are verified against the distance itself.
pub fn ring_entries(
    plan: &Path,
    dz: [f64; 3],
    ring: f64,
    rho: f64,
    window: f64,
) -> impl Iterator<Item = f64> + '_ {
    let distance = move |t: f64| {
        let p = plan.at(t);
        let h = dz[0] + (dz[1] + dz[2] * t) * t;
        let d = Vec3::new(p.x, p.y, 0.0).norm();
        ((d - ring).hypot(h), d, h, p)
    };
    // The distance and dist times its rate of change: (d - ring) d' + h h'.
    let rate = move |t: f64| {
        let (dist, d, h, p) = distance(t);
        let v = plan.velocity(t);
        let dd = if d > 0.0 {
            (p.x * v.x + p.y * v.y) / d
        } else {
            0.0
        };
        (dist, (d - ring) * dd + h * (dz[1] + 2.0 * dz[2] * t))
    };
    let approaching = move |t: f64| rate(t).1 < 0.0;
    let now = distance(0.0).0 <= rho + TOUCH_TOL
        && (approaching(0.0)
            || ring_gap_taylor(plan, dz, ring, rho).is_some_and(|(g, s, q)| pressed_back(g, s, q)));
    let rho = rho - SKIN;
    // Within rho of the ring, the plan distance from its axis is at most ring + rho.
    let searched = !now
        && window.is_finite()
        && window > 0.0
        && !never_within(&plan.plan(), ring + rho, window.min(MAX_WINDOW));
    let roots = if searched {
        // d^2 = |plan|^2 (quartic) and h^2 (quartic), as coefficient arrays.
        let (a, b, c) = (plan.a, plan.b, plan.c);
        let flat = |v: Vec3| Vec3::new(v.x, v.y, 0.0);
        let (a, b, c) = (flat(a), flat(b), flat(c));
        let d2 = [
            c.dot(&c),
            2.0 * b.dot(&c),
            b.dot(&b) + 2.0 * a.dot(&c),
            2.0 * a.dot(&b),
            a.dot(&a),
        ];
        let h2 = [
            dz[0] * dz[0],
            2.0 * dz[0] * dz[1],
            dz[1] * dz[1] + 2.0 * dz[0] * dz[2],
            2.0 * dz[1] * dz[2],
            dz[2] * dz[2],
        ];
        // A = d^2 + ring^2 - rho^2 + h^2; the contact is 2 ring d = A, squared A^2 = 4 ring^2 d^2.
        let mut big_a = [0.0; 5];
        for k in 0..5 {
            big_a[k] = d2[k] + h2[k];
        }
        big_a[0] += ring * ring - rho * rho;
        let mut octic = [0.0; 9];
        for i in 0..5 {
            for j in 0..5 {
                octic[i + j] += big_a[i] * big_a[j];
            }
            octic[i] -= 4.0 * ring * ring * d2[i];
        }
        Poly::new(octic)
            .roots_between(0.0, window.min(MAX_WINDOW), ROOT_TIME_TOL)
            .into_iter()
            .collect::<Vec<f64>>()
    } else {
        Vec::new()
    };
    let gap = move |t: f64| {
        let (dist, r) = rate(t);
        (dist - rho, r / dist)
    };
    let end = window.min(MAX_WINDOW);
    now.then_some(0.0).into_iter().chain(
        roots
            .into_iter()
            .map(move |t| polished(gap, t, end))
            .filter(move |&t| approaching(t) && (distance(t).0 - rho).abs() <= VERIFY_TOL),
    )
}

/// The distance of the point of [`ring_entries`] from the ring less `rho` at 0, its rate and
/// its second derivative: the gap [`pressed_back`] judges. With d the plan distance from the
/// axis, e = d - ring and h the height, the distance is sqrt(e^2 + h^2).
fn ring_gap_taylor(plan: &Path, dz: [f64; 3], ring: f64, rho: f64) -> Option<(f64, f64, f64)> {
    let flat = |v: Vec3| Vec3::new(v.x, v.y, 0.0);
    let (p, v, acc) = (flat(plan.c), flat(plan.b), 2.0 * flat(plan.a));
    let d = p.norm();
    let (h, h1, h2) = (dz[0], dz[1], 2.0 * dz[2]);
    let e = d - ring;
    let dist = e.hypot(h);
    (d > 0.0 && dist > 0.0).then(|| {
        let d1 = p.dot(&v) / d;
        let d2 = (v.dot(&v) + p.dot(&acc)) / d - d1 * d1 / d;
        let rate = (e * d1 + h * h1) / dist;
        let curvature = (d1 * d1 + e * d2 + h1 * h1 + h * h2) / dist - rate * rate / dist;
        (dist - rho, rate, curvature)
    })
}

/// `t`, a root of an expanded polynomial, or, when the distance there misses its root by
/// more than [`VERIFY_TOL`], the root of the distance itself found by Newton's method from
/// `t` (within [0, `end`]). The polynomial's coefficients are taken about the start of the
/// window, so a contact far from it (a ball thrown 2.7 m onto a jaw) loses digits to
/// cancellation (a root ~1e-8 s, ~1e-7 m off); `gap` (distance less the contact distance, and
/// its rate) is computed about the contact itself and keeps them. A root that already checks
/// out is returned unchanged, bit for bit.
fn polished(gap: impl Fn(f64) -> (f64, f64), t: f64, end: f64) -> f64 {
    let (g0, _) = gap(t);
    if g0.is_nan() || g0.abs() <= VERIFY_TOL {
        return t;
    }
    let (mut best, mut best_gap) = (t, g0.abs());
    let mut at = t;
    for _ in 0..8 {
        let (g, rate) = gap(at);
        if !(rate.is_finite() && rate != 0.0) {
            break;
        }
        let next = (at - g / rate).clamp(0.0, end);
        // Newton from a nearby root moves by about the root's error; a long jump is another
        // root's basin, not this one's.
        if next.is_nan() || (next - t).abs() > 1e-6 * (1.0 + t) {
            break;
        }
        at = next;
        let g = gap(at).0.abs();
        if g < best_gap {
            (best, best_gap) = (at, g);
        }
        if g <= 0.1 * VERIFY_TOL {
            break;
        }
    }
    best
}

#[cfg(test)]
/// The first time in [0, window] at which `path` comes within `dist` of the line through
/// `point` with unit normal `normal` (plan), from the normal's side and approaching.
/// Returns the time and the point of the path there.
pub fn first_line_contact(
    path: &Path,
    point: Vec3,
    normal: Vec3,
    dist: f64,
    window: f64,
) -> Option<(f64, Vec3)> {
    line_contacts(path, point, normal, dist, window).next()
}

/// Every time in [0, window], in order, at which `path` comes within `dist` of the line through
/// `point` with unit normal `normal` (plan), from the normal's side and approaching, as
/// [`first_line_contact`] finds the first (a path touching now gives 0 first; a caller may
/// refuse it, as a nose's does beyond its end, and take a later one).
pub fn line_contacts(
    path: &Path,
    point: Vec3,
    normal: Vec3,
    dist: f64,
    window: f64,
) -> impl Iterator<Item = (f64, Vec3)> + '_ {
    let s1 = normal.dot(&path.b);
    let s2 = normal.dot(&path.a);
    let now = (normal.dot(&(path.c - point)) - dist).abs() <= TOUCH_TOL && s1 < 0.0;
    let dist = dist - SKIN;
    let s0 = normal.dot(&(path.c - point)) - dist;
    let roots = if window.is_nan() || window <= 0.0 {
        Default::default()
    } else {
        Quadratic::new([s0, s1, s2]).roots()
    };
    let later = roots
        .into_iter()
        .filter(move |&t| {
            if !(0.0..=window).contains(&t) {
                return false;
            }
            let approaching = s1 + 2.0 * s2 * t < 0.0;
            let p = path.at(t);
            approaching && (normal.dot(&(p - point)) - dist).abs() <= VERIFY_TOL
        })
        .map(move |t| (t, path.at(t)));
    now.then_some((0.0, path.c)).into_iter().chain(later)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn path(c: [f64; 3], b: [f64; 3], a: [f64; 3]) -> Path {
        Path {
            c: Vec3::from(c),
            b: Vec3::from(b),
            a: Vec3::from(a),
        }
    }

    #[test]
    fn head_on_at_constant_speed() {
        // Degenerate quartic (no acceleration): still exact.
        let rel = path([1.0, 0.0, 0.0], [-2.0, 0.0, 0.0], [0.0; 3]);
        let t = first_entry(&rel, 0.0524, 10.0).unwrap();
        // Contact is taken one skin (1e-10 m) inside 2R.
        assert!((t - (1.0 - 0.0524) / 2.0).abs() < 1e-10);
    }

    #[test]
    fn equal_velocities_never_meet() {
        let rel = path([0.1, 0.0, 0.0], [0.0; 3], [0.0; 3]);
        assert_eq!(first_entry(&rel, 0.0524, 10.0), None);
    }

    #[test]
    fn touching_now_only_if_approaching() {
        let rho = 0.0524;
        let approach = path([rho, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0; 3]);
        assert_eq!(first_entry(&approach, rho, 1.0), Some(0.0));
        let leave = path([rho, 0.0, 0.0], [1.0, 0.0, 0.0], [-3.0, 0.0, 0.0]);
        // Leaves, then comes back under the acceleration: a later, real contact.
        let t = first_entry(&leave, rho, 10.0).unwrap();
        assert!((t - 1.0 / 3.0).abs() < 1e-6, "{t}");
        let rest = path([rho, 0.0, 0.0], [0.0; 3], [0.0; 3]);
        assert_eq!(first_entry(&rest, rho, 10.0), None);
    }

    #[test]
    fn a_graze_is_not_a_contact_but_a_shave_is() {
        let rho = 0.0524;
        // Passing at exactly rho: tangent double root, no approach there.
        let graze = path([-1.0, rho, 0.0], [1.0, 0.0, 0.0], [0.0; 3]);
        assert_eq!(first_entry(&graze, rho, 10.0), None);
        // Passing 1 nm inside rho: a real (very thin) contact.
        let shave = path([-1.0, rho - 1e-9, 0.0], [1.0, 0.0, 0.0], [0.0; 3]);
        assert!(first_entry(&shave, rho, 10.0).is_some());
    }

    #[test]
    fn a_push_from_rest_is_found() {
        // Touching, no relative velocity, but pressed together: a contact now (it never parts).
        let rho = 0.0524;
        let press = path([rho, 0.0, 0.0], [0.0; 3], [-1.0, 0.0, 0.0]);
        assert_eq!(first_entry(&press, rho, 1.0), Some(0.0));
        // Placed beyond the touching band, it is found after closing the gap and sinking one skin.
        let press = path([rho + 3e-9, 0.0, 0.0], [0.0; 3], [-1.0, 0.0, 0.0]);
        let t = first_entry(&press, rho, 1.0).unwrap();
        assert!(t > 0.0 && t < 1e-4, "{t}");
        let n = Vec3::y();
        let press = path([0.0, 0.024, 0.0], [0.0; 3], [0.0, -1.0, 0.0]);
        assert!(first_line_contact(&press, Vec3::zeros(), n, 0.024, 1.0).is_some());
    }

    #[test]
    fn a_pair_left_parting_at_a_crawl_but_pressed_back_is_touching_now() {
        // Fuzz seed 20261130, scene 608350: a ball thrown up off one squeezed against a cushion,
        // left one skin inside contact and parting at 1.5e-8 m/s while the other's cloth
        // friction presses them together. Its excursion out of the search sphere (1e-19 m) is
        // below the quartic's rounding: the contact must be taken now, not missed.
        let rel = path(
            [-0.0788393532864533, 0.01357778911949592, 0.0],
            [
                0.01580641141441839,
                0.09177992338791478,
                0.03692898411891887,
            ],
            [0.23975426869120361, -1.0017588997080813, -4.905],
        );
        let rho = 0.08;
        assert!(rel.c.norm() < rho && rel.c.dot(&rel.b) > 0.0);
        assert_eq!(first_entry(&rel, rho, 7.5e-3), Some(0.0));
        // Parting faster (1 mm/s, the push after an impact) it leaves the band and is found
        // on its way back in, about 2 s / |q| later.
        let away = path([rho, 0.0, 0.0], [1e-3, 0.0, 0.0], [-0.5, 0.0, 0.0]);
        let t = first_entry(&away, rho, 1.0).unwrap();
        assert!((t - 2e-3).abs() < 1e-6, "{t}");
        // Parting at a crawl but pulled apart: not a contact.
        let apart = path([rho, 0.0, 0.0], [1e-9, 0.0, 0.0], [0.5, 0.0, 0.0]);
        assert_eq!(first_entry(&apart, rho, 1.0), None);
    }

    #[test]
    fn a_ball_parting_from_a_jaw_at_a_crawl_but_pressed_back_is_touching_now() {
        // A ball in the air beside a ring (a jaw's rounded edge, radius 5 mm, at the nose's
        // height), touching it level with it, parting at 1e-9 m/s and pressed back at 1 m/s^2.
        let (ring, rho) = (0.005, 0.02625);
        let plan = path([ring + rho, 0.0, 0.0], [1e-9, 0.0, 0.0], [-0.5, 0.0, 0.0]);
        let level = [0.0, 0.0, 0.0];
        assert_eq!(ring_entries(&plan, level, ring, rho, 1.0).next(), Some(0.0));
        // The same with the parting from the height: above the ring, rising at a crawl and
        // falling back under gravity.
        let above = path([ring, 0.0, 0.0], [0.0; 3], [0.0; 3]);
        let falling = [rho, 1e-9, -4.905];
        assert_eq!(
            ring_entries(&above, falling, ring, rho, 1.0).next(),
            Some(0.0)
        );
        // Parting at a crawl and pulled away: not a contact.
        let away = path([ring + rho, 0.0, 0.0], [1e-9, 0.0, 0.0], [0.5, 0.0, 0.0]);
        assert_eq!(ring_entries(&away, level, ring, rho, 1.0).next(), None);
    }

    #[test]
    fn window_is_respected() {
        let rel = path([1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0; 3]);
        assert_eq!(first_entry(&rel, 0.05, 0.5), None);
        // A contact exactly at the window end is left to the next window, which starts touching.
        assert!(first_entry(&rel, 0.05, 0.96).is_some());
    }

    #[test]
    fn line_contact_parallel_motion_has_none() {
        let p = path([1.0, 0.024, 0.0], [1.0, 0.0, 0.0], [-0.1, 0.0, 0.0]);
        let n = Vec3::y();
        assert_eq!(first_line_contact(&p, Vec3::zeros(), n, 0.024, 10.0), None);
        let p = path([1.0, 0.5, 0.0], [0.0, -1.0, 0.0], [0.0; 3]);
        let (t, at) = first_line_contact(&p, Vec3::zeros(), n, 0.024, 10.0).unwrap();
        assert!((t - 0.476).abs() < 1e-9 && (at.y - 0.024).abs() < 1e-9);
    }
}
