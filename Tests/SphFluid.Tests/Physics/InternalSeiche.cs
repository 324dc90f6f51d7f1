using System;
using System.Collections.Generic;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The fundamental internal seiche of two liquid layers in a rectangular tank (length L along the rocking, width W):
    /// what a liquid's interface does once a lock exchange has laid the light layer over the heavy one, and so what the
    /// simulated interface is measured against (<see cref="InternalSeicheProbe"/>).
    /// <para>
    /// Period: the slow root of the two-layer dispersion relation with a free surface at k = pi / L (Lamb, "Hydrodynamics",
    /// art. 231).
    /// </para>
    /// <para>
    /// Decay: laminar viscous damping, by the energy method Keulegan used for surface seiches ("Energy dissipation in
    /// standing waves in rectangular basins", J. Fluid Mech. 6, 1959). The mode's inviscid flow (rigid lid: the free
    /// surface moves of order (rho2 - rho1) / rho2 as much as the interface) slips along the floor, the four walls and, the two
    /// layers moving opposite ways, across the interface. Each slip of amplitude U is taken up in an oscillatory (Stokes)
    /// layer of thickness sqrt(2 nu / omega), which dissipates on time average beta U^2 / 2 per unit area, beta = sqrt(mu rho
    /// omega / 2) (Landau and Lifshitz, "Fluid Mechanics", section 24); at the interface the jump is shared between the two
    /// layers in series, beta1 beta2 / (beta1 + beta2). The interior's potential flow adds mu k^3 A^2 L W sinh(2 k h) / 2
    /// per layer. With the mode's energy E = g (rho2 - rho1) a^2 L W / 4 for an interface amplitude a, the amplitude decays
    /// as exp(-gamma t), gamma = D / (2 E). The Stokes layers must be thin beside the layers and the tank for this to hold (in OilAndWater
    /// they are 9 and 14 mm thick beside 100 mm layers in a 120 mm wide tank), and the swing small beside the layers: the
    /// theory is linear.
    /// </para>
    /// </summary>
    internal static class InternalSeiche
    {
        /// <summary>Two layers at rest: upper over lower (the upper the lighter for a seiche), depths in m, densities in
        /// kg/m^3, dynamic viscosities in Pa s; free-slip walls and floor (<paramref name="NoSlipWalls"/> false) take no
        /// Stokes layer.</summary>
        internal sealed record Tank(double Length, double Width, double Gravity,
            double UpperDepth, double UpperDensity, double UpperViscosity,
            double LowerDepth, double LowerDensity, double LowerViscosity, bool NoSlipWalls = true);

        /// <summary>The fundamental internal mode's angular frequency, rad/s.</summary>
        internal static double AngularFrequency(Tank t) => Math.Sqrt(InternalRootSquared(t));

        /// <summary>
        /// The fundamental interface mode's growth rate s, 1/s, when the upper layer is the heavier (Rayleigh-Taylor: the
        /// interface's amplitude grows as cosh(s t) from rest), or 0 when the layers are stable. The same two-layer relation as
        /// <see cref="AngularFrequency"/>, whose slow root omega^2 turns negative when the lower layer is the lighter:
        /// Lamb's relation holds for any two densities, and then -omega^2 = s^2 (Chandrasekhar, "Hydrodynamic and
        /// Hydromagnetic Stability", ch. X, for unbounded layers: s^2 = g k (rho1 - rho2) / (rho1 + rho2)).
        /// </summary>
        internal static double GrowthRate(Tank t) => Math.Sqrt(Math.Max(0, -InternalRootSquared(t)));

        /// <summary>
        /// The velocity (along the tank, up), m/s, at <paramref name="x"/> from the left wall and <paramref name="height"/>
        /// above the floor, of the fundamental interface mode as its interface passes flat at its fastest, rising at
        /// rate <paramref name="amplitude"/> cos(k x): rate = s for the growing Rayleigh-Taylor mode (<see cref="GrowthRate"/>),
        /// omega for the rocking seiche (<see cref="AngularFrequency"/>). Lamb's two layers under a free surface in potential
        /// flow, phi = P cosh(k y) cos(k x) in the lower layer and (Q cosh(k y') + R sinh(k y')) cos(k x) in the upper (y'
        /// above the interface), the interface moving alike from both sides (R = P sinh(k d_lower)) and the free surface's
        /// Bernoulli condition, lambda phi + g phi_y = 0 with lambda = s^2 or -omega^2, fixing Q. Given to flat layers at rest
        /// it starts that mode alone, an interface of amplitude sinh(s t) or amplitude sin(omega t), and no surface wave.
        /// </summary>
        internal static (double Along, double Up) InterfaceModeVelocity(Tank t, double amplitude, double x, double height)
        {
            double lambda = -InternalRootSquared(t), rate = Math.Sqrt(Math.Abs(lambda)), k = Math.PI / t.Length;
            double lower = rate * amplitude / (k * Math.Sinh(k * t.LowerDepth));
            double sinh = Math.Sinh(k * t.UpperDepth), cosh = Math.Cosh(k * t.UpperDepth), gk = t.Gravity * k;
            double r = rate * amplitude / k, q = -r * (lambda * sinh + gk * cosh) / (lambda * cosh + gk * sinh);
            double along = -k * Math.Sin(k * x), up = k * Math.Cos(k * x);
            if (height < t.LowerDepth)
                return (along * lower * Math.Cosh(k * height), up * lower * Math.Sinh(k * height));
            double y = k * (height - t.LowerDepth);
            return (along * (q * Math.Cosh(y) + r * Math.Sinh(y)), up * (q * Math.Sinh(y) + r * Math.Cosh(y)));
        }

        /// <summary>The slow root omega^2 of Lamb's two-layer relation with a free surface at k = pi / L, (rad/s)^2.</summary>
        internal static double InternalRootSquared(Tank t)
        {
            double k = Math.PI / t.Length, cu = 1 / Math.Tanh(k * t.UpperDepth), cl = 1 / Math.Tanh(k * t.LowerDepth);
            double a = t.LowerDensity * cu * cl + t.UpperDensity, b = t.LowerDensity * t.Gravity * k * (cu + cl);
            double c = (t.LowerDensity - t.UpperDensity) * t.Gravity * t.Gravity * k * k;
            return (b - Math.Sqrt(b * b - 4 * a * c)) / (2 * a);
        }

        /// <summary>The amplitude's laminar decay rate gamma, 1/s (amplitude ~ exp(-gamma t)).</summary>
        internal static double DecayRate(Tank t)
        {
            double omega = AngularFrequency(t), k = Math.PI / t.Length, L = t.Length, W = t.Width;
            double h1 = t.UpperDepth, h2 = t.LowerDepth;
            double beta1 = Math.Sqrt(t.UpperViscosity * t.UpperDensity * omega / 2), beta2 = Math.Sqrt(t.LowerViscosity * t.LowerDensity * omega / 2);
            // Potentials per unit interface amplitude: phi = A cosh(k (distance from the layer's far boundary)) cos(k x) sin(omega t).
            double a1 = omega / (k * Math.Sinh(k * h1)), a2 = omega / (k * Math.Sinh(k * h2));

            // Slip amplitudes squared, integrated over each surface.
            double floor = L * W / 2 * Math.Pow(omega / Math.Sinh(k * h2), 2);
            double jump = omega * (1 / Math.Tanh(k * h1) + 1 / Math.Tanh(k * h2));
            double interfaceSlip = L * W / 2 * jump * jump;

            double walls = t.NoSlipWalls
                ? 0.5 * beta2 * (floor + EndWalls(W, a2, k, h2) + SideWalls(L, a2, k, h2)) + 0.5 * beta1 * (EndWalls(W, a1, k, h1) + SideWalls(L, a1, k, h1))
                : 0;
            double dissipation = walls
                + 0.5 * beta1 * beta2 / (beta1 + beta2) * interfaceSlip
                + t.UpperViscosity * Math.Pow(k, 3) * a1 * a1 * L * W * Math.Sinh(2 * k * h1) / 2
                + t.LowerViscosity * Math.Pow(k, 3) * a2 * a2 * L * W * Math.Sinh(2 * k * h2) / 2;
            double energy = t.Gravity * (t.LowerDensity - t.UpperDensity) * L * W / 4;
            return dissipation / (2 * energy);
        }

        /// <summary>The squared slip of a layer's potential flow, A cosh(k (distance from its far boundary)) cos(k x),
        /// integrated over the two end walls (the vertical flow there) of a layer <paramref name="h"/> deep and
        /// <paramref name="width"/> wide.</summary>
        internal static double EndWalls(double width, double a, double k, double h) => 2 * width * a * a * k * k * (Math.Sinh(2 * k * h) / (4 * k) - h / 2);

        /// <summary>The same over the two side walls along the tank (both velocity components lie in them).</summary>
        internal static double SideWalls(double length, double a, double k, double h) => length * k * a * a * Math.Sinh(2 * k * h) / 2;

        /// <summary>
        /// The largest rise of a plane interface along the tank (m) that a particle lattice of shear strength yieldRatio times
        /// the pressure (<see cref="SphFluid.Simulation.LatticeShearStrength"/>) can hold still. A rise R gives the lower
        /// layer a horizontal pressure gradient (rho2 - rho1) g R / L, a push of (rho2 - rho1) g R W d2 on the layer that the
        /// planes bounding it must carry as shear, each at most yieldRatio times its own pressure (a limit analysis: any
        /// split of the push between them stands): the interface, L W at rho1 g d1, and the floor, L W at rho1 g d1 +
        /// rho2 g d2. With <paramref name="sideWalls"/> the front and back walls along the tank carry it too, over the
        /// lower layer's depth, 2 L (rho1 g d1 d2 + rho2 g d2^2 / 2): a wall that pushes with the fluid's pressure holds the
        /// fluid's lattice beside it as the fluid's own neighbours do (DFSPH since its walls' pressure floor, WCSPH's
        /// mirrored walls throughout). So
        ///   R_max = yieldRatio L ((2 rho1 d1 + rho2 d2) W + [2 d2 (rho1 d1 + rho2 d2 / 2)]) / ((rho2 - rho1) W d2),
        /// the bracket with side walls, whatever g, and with |rho2 - rho1| when the upper layer is the heavier, whose push
        /// is the same. An interface tilted by more cannot stand still; one within it can (and may still creep into place).
        /// </summary>
        internal static double HeldRise(Tank t, double yieldRatio, bool sideWalls)
        {
            double d1 = t.UpperDepth, d2 = t.LowerDepth, rho1 = t.UpperDensity, rho2 = t.LowerDensity;
            double planes = (2 * rho1 * d1 + rho2 * d2) * t.Width;
            double walls = sideWalls ? 2 * d2 * (rho1 * d1 + rho2 * d2 / 2) : 0;
            return yieldRatio * t.Length * (planes + walls) / (Math.Abs(rho2 - rho1) * t.Width * d2);
        }

        /// <summary>
        /// Least-squares fit of y(t) = exp(-gamma (t - t0)) (A cos(omega (t - t0)) + B sin(omega (t - t0))) + C to samples
        /// (t0 the first time): for each (omega, gamma) the rest is linear, so a grid over omega in [pi / span,
        /// <paramref name="highestOmega"/>] rad/s (span: the samples' time span) and gamma in [0,
        /// <paramref name="highestGamma"/>] 1/s, refined twice around its best point, finds the global fit without a
        /// starting guess. Returns omega, gamma and the RMS residual.
        /// </summary>
        internal static (double Omega, double Gamma, double Residual) FitDampedOscillation(IReadOnlyList<double> times, IReadOnlyList<double> values,
            double highestOmega = 10, double highestGamma = 2)
        {
            if (times.Count != values.Count || times.Count < 8) throw new ArgumentException($"{times.Count} times, {values.Count} values: need 8 or more of each");
            double span = times[times.Count - 1] - times[0];
            double omegaLow = Math.PI / span, omegaHigh = highestOmega, gammaLow = 0, gammaHigh = highestGamma;
            double omegaStep = 0.02, gammaStep = 0.02, bestOmega = omegaLow, bestGamma = 0, best = double.PositiveInfinity;
            for (int pass = 0; pass < 3; pass++)
            {
                for (double omega = omegaLow; omega <= omegaHigh + 1e-12; omega += omegaStep)
                    for (double gamma = gammaLow; gamma <= gammaHigh + 1e-12; gamma += gammaStep)
                    {
                        double r = Residual(times, values, omega, gamma);
                        if (r < best) (best, bestOmega, bestGamma) = (r, omega, gamma);
                    }
                (omegaLow, omegaHigh) = (Math.Max(1e-6, bestOmega - 2 * omegaStep), bestOmega + 2 * omegaStep);
                (gammaLow, gammaHigh) = (Math.Max(0, bestGamma - 2 * gammaStep), bestGamma + 2 * gammaStep);
                omegaStep /= 20;
                gammaStep /= 20;
            }
            return (bestOmega, bestGamma, Math.Sqrt(best / times.Count));
        }

        /// <summary>The times at which the samples change sign, each interpolated linearly between its two samples.</summary>
        internal static List<double> ZeroCrossings(IReadOnlyList<double> times, IReadOnlyList<double> values)
        {
            var crossings = new List<double>();
            for (int i = 1; i < values.Count; i++)
                if (Math.Sign(values[i]) != Math.Sign(values[i - 1]) && values[i - 1] != 0)
                    crossings.Add(times[i - 1] + (times[i] - times[i - 1]) * values[i - 1] / (values[i - 1] - values[i]));
            return crossings;
        }

        /// <summary>The sum of squared residuals of the best A, B, C for this omega and gamma (3 x 3 normal equations).</summary>
        static double Residual(IReadOnlyList<double> times, IReadOnlyList<double> values, double omega, double gamma)
        {
            var m = new double[3, 4];
            var f = new double[3];
            for (int i = 0; i < times.Count; i++)
            {
                double tau = times[i] - times[0], e = Math.Exp(-gamma * tau);
                f[0] = e * Math.Cos(omega * tau); f[1] = e * Math.Sin(omega * tau); f[2] = 1;
                for (int r = 0; r < 3; r++)
                {
                    for (int c = 0; c < 3; c++) m[r, c] += f[r] * f[c];
                    m[r, 3] += f[r] * values[i];
                }
            }
            var x = Solve3(m);
            if (x == null) return double.PositiveInfinity;
            double sum = 0;
            for (int i = 0; i < times.Count; i++)
            {
                double tau = times[i] - times[0], e = Math.Exp(-gamma * tau);
                double d = values[i] - (e * (x[0] * Math.Cos(omega * tau) + x[1] * Math.Sin(omega * tau)) + x[2]);
                sum += d * d;
            }
            return sum;
        }

        /// <summary>Gaussian elimination with partial pivoting on an augmented 3 x 4 matrix; null when singular.</summary>
        static double[]? Solve3(double[,] m)
        {
            for (int col = 0; col < 3; col++)
            {
                int pivot = col;
                for (int r = col + 1; r < 3; r++) if (Math.Abs(m[r, col]) > Math.Abs(m[pivot, col])) pivot = r;
                if (Math.Abs(m[pivot, col]) < 1e-300) return null;
                for (int c = 0; c < 4; c++) (m[col, c], m[pivot, c]) = (m[pivot, c], m[col, c]);
                for (int r = 0; r < 3; r++)
                {
                    if (r == col) continue;
                    double factor = m[r, col] / m[col, col];
                    for (int c = col; c < 4; c++) m[r, c] -= factor * m[col, c];
                }
            }
            return new[] { m[0, 3] / m[0, 0], m[1, 3] / m[1, 1], m[2, 3] / m[2, 2] };
        }
    }
}
