//! A measurement of rapier itself: the cushion rebound with the nose at 7R/5 in the frictionless
//! limit.
//!
//! With the contact normal tilted by theta, the rigid answer (both contacts solved together,
//! physics.md) reverses the plan normal velocity with the factor e: the nose's push and the
//! cloth's reaction add up to a horizontal impulse through the centre. rapier applies
//! restitution once per step, after its solve, contact by contact (an end-of-step restitution
//! pass in the manner of Box2D): the bounce along the tilted normal then pushes the ball down
//! into the cloth, which takes that vertical velocity away inelastically in the next step, and
//! part of the rebound is lost. The cross-check therefore runs the frictionless limit with level
//! cushions ([`crate::shapes::ContactHeight::Level`]), and this measurement shows the loss.

use crate::crosscheck::{SceneSpec, run_both, world_config};
use crate::digest::{Parties, ShotDigest};
use crate::scenes::ImpactModels;
use crate::shapes::ContactHeight;
use serde::Serialize;
use snooker_engine::Table;

/// The first cushion rebound of a scene in both engines.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NoseRebound {
    /// Scene name.
    pub scene: String,
    /// The cushion.
    pub cushion: String,
    /// Plan normal speed before the impact, m/s (ours).
    pub approach: f64,
    /// Plan normal speed after / before in our engine (the scene's e_cushion).
    pub ours: f64,
    /// The same in rapier with the nose at 7R/5.
    pub rapier: f64,
}

/// Plan normal speed after / before of the first impact on a straight cushion.
fn first_rebound(digest: &ShotDigest, table: &Table) -> Option<(String, f64, f64)> {
    digest.impacts.iter().find_map(|i| match &i.parties {
        Parties::Cushion(_, name) => {
            let c = table.cushions.iter().find(|c| &c.name == name)?;
            let after = i.after[0].vel.dot(&c.normal);
            Some((name.clone(), i.approach, after / i.approach))
        }
        _ => None,
    })
}

/// Measures the first cushion rebound of `spec` in the frictionless limit with rapier's
/// cushions at the nose height; `None` when the scene has no cushion impact.
pub fn nose_rebound(spec: &SceneSpec, dt: f64) -> Option<NoseRebound> {
    let mut cfg = world_config(ImpactModels::Frictionless, dt);
    cfg.cushion_contact = ContactHeight::Nose;
    let (ours, rapier) = run_both(spec, ImpactModels::Frictionless, &cfg).ok()?;
    let (cushion, approach, e_ours) = first_rebound(&ours, &spec.setup.table)?;
    let (_, _, e_rapier) = first_rebound(&rapier.digest, &spec.setup.table)?;
    Some(NoseRebound {
        scene: spec.name.clone(),
        cushion,
        approach,
        ours: e_ours,
        rapier: e_rapier,
    })
}
