//! The prose of docs/validation.md: how the cross-check works and why its tolerances are what
//! they are.

/// How the cross-check works and why its tolerances are what they are.
pub const METHOD: &str = r#"## What is compared

Every scene of `validation/scenes/` is simulated by our event-driven engine and by
[rapier](https://rapier.rs) (`rapier3d-f64` 0.36.1), built from the same `Setup`:

- **Balls**: dynamic spheres of the scene's radius and mass (rapier's solid-sphere inertia is
  2MR²/5, as ours). **Cloth**: a fixed half-space. **Pockets**: sensor spheres of radius
  (fall radius − R) at the height of a ball's centre, so that a ball overlaps one exactly when
  its centre enters the fall circle, the engine's rule; the ball is then removed.
- **Cushions and jaws**: capsules along each nose and facing, and spheres at the jaws, placed so
  that a ball on the cloth touches them where the engine says (centre R cos θ from the nose line
  in plan, jaw contact r_j + R cos θ from the jaw centre). With friction on they touch at the
  nose height h = 7R/5 with the normal tilted by θ (thesis §6.2). In the frictionless limit
  they touch level with the ball's centre (see "By-design differences").
- **Friction and restitution** per pair from the scene's parameters (a contact hook): cloth
  μ_s, no bounce; ball-ball e and, with friction, μ_bb; cushion e_e and, with friction, μ_w.
  In the frictionless limit the ball-ball and cushion friction are zero.
- **What rapier lacks**, applied as external loads every step: rolling resistance (force
  −Mμ_r g v̂ and torque −(Iμ_r g/R') e_z × v̂ on a rolling ball, R' = R − δ/2 the arm of rapier's
  contact point, which keeps it rolling while it decelerates at μ_r g, thesis §2.4.2) and the cloth's resistance to sidespin (torque −I·22 rad/s²
  about the vertical, thesis §5.3) on a ball on the cloth (in the air the spin is frozen,
  §6.1.6), each clamped so that a step never reverses the motion. rapier's friction model is set
  to Coulomb (one friction cone per contact, no twist constraint), contact recycling off.
- **Resting depth.** rapier's contacts are soft: a resting ball sinks δ into the cloth, the
  static deflection g/(2π·60 Hz)² = 6.9×10⁻⁵ m of its contact spring (measured once on a ball
  left to settle until its depth stops changing, which takes about 3.5 s: rapier corrects
  penetration through the positions, so a sinking ball's velocity reads zero). Every ball on the
  cloth is placed at that depth.

From each engine's run the same *shot digest* is taken (`validation/src/digest.rs`): the
impacts in order (ball pairs, cushions or jaws by name, pots by pocket, landings of airborne
balls), their times, every involved ball's velocity and spin just before and just after, the
slide-to-roll times and speeds, and the final positions. rapier's events are read from its
steps: an impact starts in the step in which a contact first carries an impulse (its time is
where the gap before the step, closing at the approach speed, reaches zero; its state before is
the one at the start of that step, its state after the one at the end of the last step in which
the contact pushes); a ball lands in the step in which its cloth contact pushes again after a
flight (its state after is the one once the soft cloth has stopped its fall, a few steps
later); a ball rolls while its cloth contact sticks (friction below the Coulomb limit) with a
slip below one step's worth (3.5 μ_s g dt); a ball is pocketed when it overlaps a pocket
sensor, and since rapier finds overlaps at the start of a step, before it moves the bodies, the
crossing of the fall circle is interpolated back over the step before. Both digests are reduced to what both can resolve: contacts closing slower than
2 mm/s (twice our engine's micro-collision speed `MIN_SEPARATION`) are resting contacts, and
repeats of one contact within two steps are one impact.

**Time step.** dt = 10⁻⁴ s, from the study at the end. The largest differences over the set
are set by shares that do not depend on the step (the soft contact's: slow and grazing
impacts, the sink's shift of a rolling speed), which stay put as dt halves, except the velocity
after a curved impact (a jaw, a ball pair), whose share is the turn of the contact's normal
over one step and shrinks with dt, well within its tolerance at 10⁻⁴ s. Every run passes at
every step of the study; a finer step would multiply the runtime for no verdict it changes,
and 10⁻⁴ s keeps the integration tests (`validation/tests/crosscheck.rs`) within the CI
budget.

## How a verdict is reached: whole shot or stretch by stretch

A run is compared over the whole shot when none of its impacts differs by design between the
engines, and stretch by stretch when one does.

**Frictionless impacts: the whole shot.** In the frictionless limit both engines' impacts are
the same law (Newton's and the energetic restitution coincide; physics.md, "Analytic limits"),
so the runs differ only by the time step and the soft contact, and those differences stay
small as they are carried through the shot. The verdict passes when the impact sequences are
identical and every figure is within its tolerance, accumulated over the whole shot (below).
This is the stronger test where it applies: it checks the impacts themselves and how errors
propagate through them. (A frictionless run with a landing, `jump-*`, goes stretch by stretch:
the landing differs by design, below.)

**Frictional impacts: stretch by stretch.** With friction the two engines' impact models
differ by design (ours: energetic restitution, Coulomb friction integrated over the normal
impulse with its slip directions free to turn, thesis §6.1, §6.2; rapier: Newton's restitution,
Coulomb friction resolved once per step). The difference is bounded only by the friction
impulse, a good part of the approach speed (about 1 m/s for a hard cushion impact). Carried
forward it swamps every later figure (the whole-shot tolerances after one frictional impact
reach metres of final position), and a rebound a few degrees apart sends a ball near a corner
to another cushion (issue 11; the scenes `corner-*` show it: the whole-shot comparison, the
former method, fails them on the sequence). A whole-shot comparison can then
neither see an error in a motion law after the first impact nor tell a different sequence
from an error. So each run with friction is cut at every impact whose models differ by design
(every ball-ball and cushion or jaw impact, and every landing) and rapier is **re-seeded** from
our engine's state just after it: every ball's position, velocity and spin (a ball on the
cloth at the depth rapier's balls rest in it; a rolling ball rolling on rapier's contact point,
at mid-depth, so that it does not start with a slip of δ/2R of its speed; an airborne ball at
its height; pocketed balls out of play). Each stretch between two cuts is then compared on its
own:

- the impact that ends it (the *detection of the next event*) must be the same in both, and
  so must any pot before it; its time, the slide-to-roll transitions within the stretch and the
  velocities and spins **just before** the impact are checked against the derived tolerances,
  accumulated from zero at the start of the stretch (the *motion laws* over the stretch); the
  last stretch, which ends at rest, checks the final positions;
- the **impact's own difference**, the change of each ball's velocity and spin across it in
  one engine against the other, is measured against its by-design bound (below).

So every impact's difference is measured, and every motion law and every detection is checked
over the whole shot, stretch after stretch, without the by-design differences of earlier
impacts in the way. The whole-shot comparison of these runs is still made and reported as
information (no verdict). The verdict passes when every stretch passes; `snooker validate`
exits non-zero when any run fails.

What this cannot see: an error in a frictional impact smaller than what friction may explain
(for example a wrong direction of the friction impulse) is within the by-design bound; the
impact models are checked against the thesis's measurements and analytic limits elsewhere
(`engine/tests/impact_models.rs`). What it does see is shown by errors planted in our engine
(`validation/tests/crosscheck.rs`): a 2 % error in restitution or rolling resistance fails the
whole-shot comparison; a 2 % error in rolling resistance from the first cushion impact on fails
a stretch (the whole-shot tolerances after that impact are far too wide for it); a cushion
impact resolved twice over fails its impact-difference bound.

How wide "by design" is, in numbers (a review, on cushion-15 with friction): the bound on the
spin change at the cushion, 15.7 rad/s, is larger than the change itself (ours 6.4 rad/s,
rapier's 2.7), and the bound on the velocity change, 0.165 m/s, nearly the approach's normal
speed: such a run's verdict says the shot between impacts agrees, next to nothing about the
frictional impact law, which only the impact-model tests check. Some whole-shot tolerances on
the final position after a cushion exceed the table's length (5.11 m, 43.1 m in the table
below): reported, not a check. Ten of the twelve compliant runs lie below the compliant
cushion's knee, where it is the rigid cushion, and repeat their mathavan runs.

## Tolerances, derived

Each tolerance is computed event by event from our engine's digest and the known differences
between the runs; none is a fitted number. With a_s = μ_s g, a_r = μ_r g:

- **Time step.** rapier resolves every discrete change (impact, landing, start of rolling, pot)
  at a step boundary: each may shift by one step dt, and within a step the cloth's friction
  changes a speed by up to a_s dt and a sliding ball's spin by 5a_s dt/2R. rapier's state after
  an impact is the state at the end of its last step, its state before the one at the start of
  its first.
- **Soft contact.** A ball sinks δ into rapier's cloth (the largest depth seen in the run,
  about 6.9×10⁻⁵ m: the static deflection g/(2π·60 Hz)² of rapier's contact spring against a
  fixed body) and rapier puts the contact point at mid-depth: the ball rolls on R' = R(1 − ε),
  ε = δ/2R. From the conservation of angular momentum about the contact point, the rolling
  speed (k²v₀ + 0.4kω₀R)/(k² + 0.4), k = R'/R, moves by at most ε(0.41|v₀| + 0.13|ω₀|R); the
  sliding time by at most ε(|ω₀|R/3.5a_s + 1.43 t_slide); while sliding, the friction's torque
  arm is R' too, so the spin drifts by ε(5a_s/2R) per second of sliding.
- **Propagation.** A speed error dv carried over a stretch of travel τ arriving at speed v shifts
  the arrival by τ dv/v; an impact passes velocity errors on with gain at most 1 (Newton's law,
  equal masses) plus a_s times its time error; a ball rolling to rest from speed v with a speed
  error dv stops v dv/a_r further or shorter and up to (v²/2a_r)(dv/v) to the side, and a time
  error t' of the start of its roll moves it by v t'. The bounds accumulate in time order over
  all balls (conservatively): over the whole shot, or from zero at the start of each stretch.
  The state just before an impact is allowed the accumulated share alone; the state after it
  also the models' difference below.
- **Cushions at the nose height under a sunk ball.** A ball resting δ lower meets a nose whose
  contact normal is tilted by θ when its centre is δ tan θ nearer the nose line in plan: the
  impact comes up to δ tan θ/v_n later (v_n the plan approach speed), which matters only for a
  grazing approach.
- **Curved contacts** (ball pairs, jaws; ρ the distance between the centres at the touch, 2R or
  r_j + R cos θ in plan). rapier takes a contact's normal from the positions at the start of the
  step, up to one step's relative travel before the touch: turned by up to v_t dt/ρ (v_t the
  relative speed across the normal). A path offset sideways by h meets the contact with its
  normal turned by h|v|/(ρ v_n); h accumulates from the velocity errors that may point anywhere
  (those passed on by impacts; a slide's end changes a speed along the path) over the travel
  since. A normal turned by φ moves the velocities after by up to k(1 + e)(v_n + v_t)φ, k = 1/2
  for a ball pair (equal masses), 1 at a jaw. Grazing contacts amplify errors: a path a fraction
  of a millimetre aside meets a jaw with its normal turned by degrees.
- **Level cushions under a sunk ball.** The sunk ball meets a level cushion slightly below its
  axis: the normal tilts by δ/(R + r_c), giving a vertical velocity of up to (1 + e)v_n δ/(R + r_c).
- **Landing.** Until it touches, an airborne ball's vertical velocity changes at g: rapier's state
  at the start of the landing step differs from ours at the touch by up to g dt.
- **Landing (by design).** Our engine neglects the cloth's friction percussion when an airborne
  ball lands (thesis §6.1.6); rapier's cloth, which does not bounce, applies up to μ_s times the
  normal impulse M v_z: the velocities after differ by up to μ_s v_z and the spins by 5/2R times
  it, with any impact models.
- **With friction (by design).** Each engine's friction impulse is at most μ times the normal
  impulse, so the velocities after an impact may differ by up to twice that (2μ_bb(1 + e)v_n/2
  for a ball pair, 2(μ_w + μ_s sin θ)(1 + e)v_n/cos θ at a cushion, the normal impulse along the
  tilted normal being (1 + e)v_n/cos θ per unit mass) and the spins by 5/2R times it.
- **An impact's own difference.** The two engines' changes of velocity across one impact may
  differ by the by-design part above, plus what their slightly different incoming states explain
  (the normal impulse is linear in the approach speed: an incoming velocity difference d changes
  it by at most (1 + e)d per unit mass, times (1 + μ) with its friction; for a ball pair both
  balls' differences add up; at a cushion divided by cos θ), plus the turn of a curved contact's
  normal above, plus the cloth's friction a_s (and gravity for a landing) over the time the
  impact spans in rapier (from the start of its first step to the end of its last); the spins
  by 5/2R times the friction parts and the sidespin rate over that time.

## By-design differences

- **Restitution.** In the frictionless limit Newton's and the energetic (Stronge) restitution
  coincide, so both engines must agree to the tolerances above over the whole shot. With
  friction they differ by design: those runs are compared stretch by stretch, each impact's
  difference against its bound.
- **Cushion contact height in the frictionless limit.** rapier applies restitution once per
  step, after its solve, one contact at a time (an end-of-step restitution pass in the manner
  of Box2D). At a nose at 7R/5 the bounce along the tilted normal pushes the ball into the
  cloth, and the cloth takes that vertical velocity away inelastically in the next step: rapier
  loses part of the rebound (measured below), where the rigid answer (nose and cloth solved
  together) reverses the plan normal velocity with e exactly, as our engine does. Without
  friction a level contact is the same impact (the nose's push plus the cloth's reaction is a
  horizontal impulse through the centre either way), so the frictionless runs use level
  cushions; the runs with friction, where the contact height matters, use the nose at 7R/5.
- **Landing.** Our engine neglects the landing's friction percussion (thesis §6.1.6), rapier's
  cloth has it; the landing is a cut of the frictional runs and its bound is part of the
  frictionless runs' propagated tolerances. Our airborne balls meet cushions and pockets by
  their plan position (the book's Limitations page); the scenes keep airborne balls clear of
  them.
- **Hypersensitive shots.** Where a grazing contact amplifies the step's share (a ball glancing
  off one jaw into the other, rattling in a corner's jaws) the tolerances after it grow to
  metres and the sequences part: such a shot is chaotic and is not in the verdict set (tried:
  a ball along the middle pocket's mouth from jaw to jaw; a rattle in a corner's jaws).
- **Touching balls.** Our engine resolves a pack as a sequence of pairwise impacts; rapier solves
  all contacts of a step together. The break-off is compared up to the first impact on the
  pack (which ball, when), not the states after it; its outcome is chaotic and is compared
  through statistics (measured, no verdict).
- **Soft contact.** The sink δ above; rapier's balls rest δ lower, so final positions are
  compared in plan.
"#;

pub(super) const STATISTICS: &str = "Once the pack is struck, tiny differences grow until individual \
outcomes have nothing in common. Our engine is run on an ensemble of the shot with the cue \
ball's heading turned by multiples of 10⁻⁴ rad (−8 … 8, far below a player's aim) and rapier's \
outcome is set beside the ensemble. Ball-ball impact counts are not comparable by construction: \
rapier's pack contacts start from rest and carry force without an approach speed, so they do \
not count as impacts. The number of balls that moved is where the engines really differ, and \
we attribute it to the treatment of touching balls: pairwise sequential impacts (ours) pass the \
momentum along each line of centres in turn and eject the far balls of the pack, while rapier's \
simultaneous solve shares it among all the touching balls at once, which then move off more \
together. The rigid-body model does not decide between the two (simultaneous contacts of rigid \
balls have no unique outcome); which is closer to real balls is a question for measured \
break-offs, not for this cross-check.\n";

pub(super) const NOSE: &str = "The first cushion impact of each cushion scene, frictionless, rapier's \
cushions at the nose height 7R/5 (cloth friction off during the impact, as the frictionless \
limit asks): the plan normal velocity after the impact over the one before. Ours is the scene's \
e_e = 0.98 (rolling resistance aside); rapier's end-of-step restitution pass loses the vertical \
part of the bounce to the cloth (see \"By-design differences\"), which is why the frictionless \
comparison uses level cushions.\n";

pub(super) const CONVERGENCE: &str = "The scene set in the frictionless limit at halving time steps: the \
largest difference between the engines of each figure over the scenes compared over the whole \
shot (the break-off's first impact included; the `jump-*` scenes, compared stretch by stretch \
because their landing differs by design, count in the verdicts only). A figure whose largest \
difference stays put as dt halves is set by a share that does not depend on the step (the \
soft contact's); one that shrinks, by the step's.\n";
