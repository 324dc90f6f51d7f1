#ifndef SPHFLUID_DIVERGENCE_FREE_SOLVER_INCLUDED
#define SPHFLUID_DIVERGENCE_FREE_SOLVER_INCLUDED

// Divergence-free SPH (Bender & Koschier 2015, "Divergence-Free Smoothed Particle Hydrodynamics", SCA 2015; and
// 2017, "Divergence-Free SPH for Incompressible and Viscous Fluids", IEEE TVCG 23), written in the number density
// of the density-contrast formulation (SphDensityPressure.hlsl) so that phases of different particle mass meet
// without a spurious force: the constraint is delta_i = delta0_i = rho0_i / m_i, and the pressure force is the same
// antisymmetric pair force as WCSPH's, F_i = -sum_j (q_i + q_j) gradW_ij - sum_b (omega_ib q_i + q_b) gradW_ib with
// q = p / delta^2, each wall particle b carrying a q_b of its own (walls as unknowns, below), and omega_ib the wall
// particle's volume at i's rest number density (SphBoundary.hlsl's WallWeight).
//
// Rate of change of the number density (continuity equation, walls at their own velocity):
//   D delta_i / Dt = sum_j (v_i - v_j) . gradW_ij + sum_b omega_ib (v_i - v_b) . gradW_ib
// A q_i alone changes v_i by -(dt / m_i) q_i G_i, G_i = sum_j gradW_ij + sum_b omega_ib gradW_ib, and each fluid
// neighbour's by +(dt / m_j) q_i gradW_ij, so D delta_i / Dt changes by -dt q_i / alpha_i with the DFSPH factor
//   alpha_i = 1 / ( |G_i|^2 / m_i + sum_j |gradW_ij|^2 / m_j )        (walls in G_i only: they do not move)
// (the papers' alpha_i in number-density form; 0 where the sum vanishes: an isolated particle has nothing to push).
// Each solve is a Jacobi iteration on q, every particle taking its neighbours' q as fixed:
//   constant density   q_i = max(delta*_i - delta0_i, 0) alpha_i / dt^2,  delta*_i = delta_i + dt D delta_i / Dt (v*)
//   divergence-free    q_i = max(D delta_i / Dt, 0) alpha_i / dt
// (only compression is corrected: a free surface is under-dense by construction), each fluid particle's step scaled
// by _SolverRelaxation (the setting; 1 is the papers' step). On the lattice the full step multiplies the residual of a
// wave of about 3.6 spacings by 1 - 2.82 (the cubic spline at 2 spacings), so that wave overshoots and grows with each
// iteration, and since expansion is never corrected the overshoot stays as pressure noise; at 1 / lambda_max
// (SolverRelaxation.cs) no wave overshoots, at more iterations. The error each iteration
// reports, per particle, is max(delta*_i / delta0_i - 1, 0) (compression) and max(D delta_i / Dt, 0) / delta0_i
// (1/s); a solve stops once their average over each phase's particles is within its tolerance, after at least two
// iterations.
// Warm start: each solve begins with a fraction of the q the same solve summed up in the previous sub-step
// (q, not the papers' kappa, is kept: it is a pressure term that does not scale with dt, so a changed dt needs no
// rescaling). Half, not all, as Implicit Incompressible SPH starts from half the previous pressure (Ihmsen et al. 2014):
// the Jacobi solves only add pressure, so a surplus kept where the flow has changed stays (Headless/tools/
// warm-start-scan.sh: 0.75 halves the iterations but leaves a resting tank four times the kinetic energy; 1 diverges).
// The Chebyshev solve may take pressure back, but a whole warm start of its constant-density solve leaves the
// divergence-free solve more to do, and without its own warm start the divergence-free solve leaves the fluid more
// compressed (the same tool with --solver-iteration chebyshev; Headless/docs/accuracy-for-time.md, "What would close
// it"). Nor does carrying only
// the long waves whole help (half a particle's own q plus half its neighbours' average, which keeps the hydrostatic
// field): the constant-density solve shortens, the divergence-free solve more than doubles and the fluid gains energy
// (Headless/experiments/smoothed-density-warm-start.patch).
#define DENSITY_WARM_START 0.5
#define DIVERGENCE_WARM_START 0.5

// Chebyshev acceleration (the Chebyshev semi-iterative method; Golub and Varga 1961, "Chebyshev semi-iterative methods,
// successive overrelaxation iterative methods, and second order Richardson iterative methods"; as written for a
// preconditioned operator whose eigenvalues lie in [a, b] in Saad 2003, "Iterative Methods for Sparse Linear Systems",
// section 12.3). The relaxed Jacobi step removes a pressure wave's residual by the factor 1 - lambda, lambda its
// eigenvalue of the relaxed, diagonally scaled operator. The longest wave a fluid column of n spacings carries has
// lambda of about 6 / n^2 (Wendland C2 at 2.85 spacings relaxed to 0.3), so the Jacobi solve needs iterations in
// proportion to n^2, which is why it grew from 12 at 4 160 particles to the cap of 100 at 100k. Chebyshev's steps
//   d_k = beta_k d_{k-1} + gamma_k z_k        (z_k the relaxed Jacobi step of round k, d_k the step applied)
// with rho_0 = 1 / sigma, rho_k = 1 / (2 sigma - rho_{k-1}), sigma = (b + a) / (b - a), beta_k = rho_k rho_{k-1},
// gamma_k = 2 rho_k / (b - a) (and d_0 = z_0 / theta, theta = (b + a) / 2) shrink every residual with lambda in [a, b]
// by the least factor a polynomial of that degree can, in iterations proportional to sqrt(b / a), that is to n.
// [a, b] comes from the host (ChebyshevBounds.cs): b from the lattice's stiffest wave, and at least the relaxed Jacobi
// step's bound of 2, a from the longest wave of the spawned fluid's depth. A wave below a is still damped, more slowly;
// one above b grows, so b has a margin: a loosely held fluid is disordered and carries waves stiffer than the lattice's.
// The polynomial takes back pressure where a long wave overshoots, which the compression-only step above cannot: with
// it the steps stay compression-only and the fluid rose (OilAndWater at 25 900 particles, 0.3 s: 2.3 constant-density
// iterations a sub-step, but its potential energy grew by 0.11 J and its water expanded 3.5 % against the Jacobi solve's 0.2 %). So the
// accelerated solve takes signed steps and projects the pressure each particle has summed in this solve onto q >= 0
// (IISPH's projected Jacobi; Ihmsen et al. 2014): d_k = max(Q + beta_k d_{k-1} + gamma_k z_k, 0) - Q, Q the q applied
// so far in this solve, warm start included. The wall particles' signed steps take a third of the fluid's relaxation
// (CHEBYSHEV_WALL_SHARE): at WALL_RELAXATION's 0.5 with the fluid's 0.3 OilAndWater went to NaN within 0.033 s (4 160
// particles); at 0.1 it held, as below.
// A solve stopped after a few rounds leaves the polynomial's swing through zero on the waves between a and b, and a loose
// constant-density solve stops that early: its overshoots stay in the velocities, hidden from the compression-only error,
// for the divergence-free solve to remove (25 of its rounds a sub-step at 1 %, against 2 at 0.1 %) or, at a shallow depth,
// to lift the fluid. So the constant-density solve takes accelerated steps only at tolerances below one that grows with
// the depth (ChebyshevBounds.AcceleratesDensitySolve, _AcceleratedDensitySolve), and the Jacobi solve's steps above it.
#define CHEBYSHEV_WALL_SHARE (1.0 / 3.0)

// (beta_k, gamma_k, rho_k) of a round from rho_{k-1} (0 before the solve's first round) for eigenvalues in [low, high].
float3 ChebyshevWeights(float previousRho, float low, float high)
{
    float theta = 0.5 * (high + low);
    float delta = 0.5 * (high - low);
    float sigma = theta / delta;
    if (previousRho <= 0.0)
        return float3(0.0, 1.0 / theta, 1.0 / sigma);
    float rho = 1.0 / (2.0 * sigma - previousRho);
    return float3(rho * previousRho, 2.0 * rho / delta, rho);
}

// The step d_k a particle applies: max(Q + beta d_{k-1} + gamma z, 0) - Q (Chebyshev acceleration, above).
float ProjectedChebyshevStep(float applied, float previousStep, float jacobiStep, float3 weights)
{
    return max(applied + weights.x * previousStep + weights.y * jacobiStep, 0.0) - applied;
}

// A particle with fewer neighbours (fluid and wall particles within H) than this is left out of the divergence-free
// solve, as SPlisHSPlasH does for "particle deficiency": at a support of 2 spacings a full neighbourhood holds about
// 33, and a spray particle's few pairs give a Jacobi step with no neighbours to share it, which overshoots (a dam
// break's splash at the far wall diverged within 0.1 s without this).
#define DIVERGENCE_MIN_NEIGHBOURS 20u

// Wall contact. The solves correct compression only, so a particle that is under-dense (at a free surface, or left
// behind by neighbours moving away) feels nothing from a wall it moves into: its own D delta_i / Dt can be negative
// while its wall part, sum_b omega_ib (v_i - v_b) . gradW_ib, is positive. For such a particle the divergence-free
// condition is applied to the wall part alone in the drift, after the constant-density solve (Drift): the same Jacobi step as the
// divergence-free solve's with the walls as the only neighbours, q = rate alpha_w / dt with alpha_w = m_i / |G_w|^2,
// which removes exactly the velocity along G_w = sum_b omega_ib gradW_ib that compresses the wall side
// (WallContactVelocity in SphBoundary.hlsl, which WCSPH uses too; there only for particles already closer to the walls
// than at rest, beside its contact damping). It has no speed of sound in it and no time-step bound of its own.
// It also acts on a particle at or above rest density once it is within DIVERGENCE_CONTACT_GAP spacings of a wall's
// face (WallGap, SphBoundary.hlsl; at rest beside a flat wall a particle is half a spacing from it): the density
// constraint, the walls' included, does not hold the fluid beside a wall at its lattice place. Wall and fluid
// particles weigh alike, so a particle that moves towards a wall while its fluid neighbours rearrange keeps its own
// density and its wall particles' at rest, and nothing pushes back: in the lock exchange at 2.9 spacings oil beside
// the front and back walls drifted to within a hundredth of a spacing of the faces at rest density, the wall
// particles beside it within 0.6 % of theirs (WallCreepProbe at 10e0e0f), and the last-resort clamp caught 14 in the
// first second and 108 by 6.5 s. Read off the walls' number density instead (a quarter spacing closer than a flat
// wall's rest place, as WCSPH's gate reads it at the place itself), the gate held them too, but at an edge or corner
// of the container that sum exceeds a flat wall's anywhere, so the contact acted on every particle there and kept
// oil in the floor's edges: 1.6 to 2.6 % of the floor layer oil from 3 s to 6.5 s of the scene's lock exchange,
// 0.34 % (one particle, in a corner) by distance. The gate reads where the drift would end, so a particle does not first
// cross the gap for a sub-step. A quarter spacing is halfway from the rest place to the face; 0.1 and 0.4 held too
// (the 2.9-spacing copy's closest centre in its first second 0.100 and 0.240 spacings from a face, against 0.148;
// the resting tank of DivergenceFreeTankTests within its tolerance at both). Since the walls' pressure has a floor at the
// fluid's (WallStepAtLeast, below) the fluid no longer drifts there, and the gap is a backstop: without it the
// 2.9-spacing copy's closest centre in its first second is 0.231 spacings from a face, with no clamp hit.
#define DIVERGENCE_CONTACT_GAP 0.25

// Walls as unknowns. With the fluid particle's own q mirrored onto the wall (Akinci et al. 2012, "Versatile rigid-fluid
// coupling for incompressible SPH": F_i = -sum_b omega_b q_i gradW_ib) the wall term is the adjoint of the walls' part of
// the continuity equation, so it does no work, but in a uniform pressure it leaves a particle beside a wall a net push
// q_i G_w into it: in a resting tank the floor row sank from half a spacing above the wall face to a quarter, and the
// column lost 2.6 % of its height in 0.25 s. So each wall particle b is a constraint of its own, as the fluid's are:
//   delta_b = sum_f W_bf + sum_b' omega_bb' W_bb',   D delta_b / Dt = sum_f (v_f - v_b) . gradW_fb
// with the rest number density of the fluid around it (Shepard-weighted) as its target and the walls around it weighed
// at that same rest number density (omega_bb', WallWeight's scale Shepard-weighted: a wall whose own sum exceeded the
// fluid's rest density asked for a density no motion of the fluid could give, see SphBoundary.hlsl; a sphere's own shells,
// weighed up for the fluid outside, count at rest instead of summed: Passes/Walls.hlsl), and q_b moves the fluid by
// -(dt / m_f) q_b gradW_fb: the force on the fluid, -(omega_ib q_i + q_b) gradW_ib, is again the constraints' adjoint.
// Its Jacobi factor has no |G|^2 term (a wall does not move): alpha_b = 1 / sum_f |gradW_bf|^2 / m_f. Its step is
// relaxed by WALL_RELAXATION, as IISPH's relaxed Jacobi is (Ihmsen et al. 2014, "Implicit incompressible SPH"); not
// measured without it. A wall particle that has lost its fluid gets q_b = 0: one that kept its q summed it into the warm
// start every iteration, and the tank diverged within 0.25 s. A wall particle that reaches little fluid has its factor
// scaled by its fluid share sum_f W_bf / (WALL_FULL_SHARE delta0_b), so that one fluid particle near the edge of its
// support is not asked to remove the wall's whole excess (the oil-and-water scene, whose walls are not on the fluid's
// lattice, blew up in its first frame without it). Wall particles keep their warm start per sorted slot, cleared
// whenever the boundary is re-sorted.

#define WALL_RELAXATION 0.5
#define WALL_FULL_SHARE 0.25

// The wall's pressure at least the fluid's. Its own constraint gives a wall particle pressure only while it is
// compressed, and a fluid particle beside a wall whose q_b is below its own q is pushed into the wall: in a uniform q
// the fluid pairs push it by -2q sum_j gradW_ij, which a complete neighbourhood's wall part balances only with
// -(omega q + q_b) G_w at q_b = q. The pairs with walls then cost half what a fluid pair costs, and the fluid drifts
// towards the walls while every constraint holds (WallCreepProbe: 122 centres within 0.35 spacings of the front and
// back walls of the 2.9-spacing lock exchange at 1 s, held off the faces only by the wall contact above; 13 with this).
// So each round of the constant-density solve raises a wall particle's q_b to the q the fluid around it has applied in
// this solve, Shepard-weighted: the pressure boundary of Band et al. 2018 ("Pressure boundaries for implicit
// incompressible SPH", ACM TOG 37), without its hydrostatic term (below), as a floor under the wall's own constraint rather than
// in its place. Where the wall is compressed its own step rules and the floor adds nothing. Added to the wall's own step
// instead, the two pushed twice (the stretched-lattice tank's first frame rose at 0.12 m/s against 0.03). The floor is not
// the adjoint of a constraint, so it can do work: applied in the divergence-free solve as well, it raised the still
// sphere's pool in SphereWake 0.0068 J above its spawn's energy; in the constant-density solve alone the pool stays below
// it, and the divergence-free solve's q, a correction of the velocity's divergence after the drift, holds nothing up.
// Band et al.'s hydrostatic term, rho_f g . (x_b - x_f) added to each fluid neighbour's q (m_f^2 / rho0_f per pascal), is
// left out for the same reason: with it the resting tank's column was no closer to its spawned height at 1 s (-0.31 %
// and -0.36 %, Chebyshev and Jacobi, against -0.37 % and -0.33 %: DivergenceFreeTankTests) with 1.5 and 1.2 times
// the kinetic energy, and SphereWake's still pool rose 0.0006 J above its spawn's energy (Headless/tools/experiment.sh
// --baseline hydrostatic-floor).
float WallStepAtLeast(float step, float applied, float fluidStiffness)
{
    return max(step, fluidStiffness - applied);
}

// alpha_b of a wall particle from its fluid sums: sum_f W_bf, the fluid's rest number density and sum_f |gradW_bf|^2 / m_f.
float WallFactor(float fluidNumberDensity, float restNumberDensity, float squaredGradientsOverMass)
{
    float share = min(1.0, fluidNumberDensity / (WALL_FULL_SHARE * max(restNumberDensity, 1e-20)));
    return squaredGradientsOverMass > 1e-20 ? share / squaredGradientsOverMass : 0.0;
}

// 1 / ( |G|^2 / m_i + sum |gradW_ij|^2 / m_j ), 0 where nothing can be pushed.
float DivergenceFreeFactor(float3 gradientSum, float squaredGradientsOverMass, float particleMass)
{
    float denominator = dot(gradientSum, gradientSum) / particleMass + squaredGradientsOverMass;
    return denominator > 1e-20 ? 1.0 / denominator : 0.0;
}

// q of the constant-density solve and the particle's relative compression (its error).
float2 DensityStiffness(float numberDensity, float densityRate, float restNumberDensity, float factor, float dt)
{
    float predicted = numberDensity + dt * densityRate;
    float excess = max(predicted - restNumberDensity, 0.0);
    return float2(excess * factor / (dt * dt), excess / restNumberDensity);
}

// q of the constant-density solve with the sign of its residual (the accelerated solve's z).
float SignedDensityStiffness(float numberDensity, float densityRate, float restNumberDensity, float factor, float dt)
{
    return (numberDensity + dt * densityRate - restNumberDensity) * factor / (dt * dt);
}

// q of the divergence-free solve with the sign of its residual.
float SignedDivergenceStiffness(float densityRate, float factor, float dt)
{
    return densityRate * factor / dt;
}

// q of the divergence-free solve and the particle's relative rate of compression, 1/s (its error).
float2 DivergenceStiffness(float densityRate, float restNumberDensity, float factor, float dt)
{
    float rate = max(densityRate, 0.0);
    return float2(rate * factor / dt, rate / restNumberDensity);
}

// Velocity change of fluid particle i from the pair (i, j): -(dt / m_i) (q_i + q_j) gradW_ij.
float3 StiffnessVelocityPair(float stiffnessI, float stiffnessJ, float3 gradient, float dtOverMass)
{
    return -dtOverMass * (stiffnessI + stiffnessJ) * gradient;
}

// Velocity change of fluid particle i from wall particle b: -(dt / m_i) (omega_ib q_i + q_b) gradW_ib.
float3 StiffnessVelocityWall(float stiffnessI, float stiffnessB, float weight, float3 gradient, float dtOverMass)
{
    return -dtOverMass * (weight * stiffnessI + stiffnessB) * gradient;
}

#endif
