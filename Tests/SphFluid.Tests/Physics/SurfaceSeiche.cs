using System;
using System.Numerics;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The fundamental surface seiche of one liquid in a rectangular tank (length L along the sloshing, width W, depth h):
    /// what a tank whose free surface is tilted does, and so what the simulated surface is measured against
    /// (<see cref="SurfaceSeicheTests"/>).
    /// <para>
    /// Period: the linear standing wave at k = pi / L, omega^2 = g k tanh(k h) (Lamb, "Hydrodynamics", art. 227 and 257).
    /// A swing of amplitude a changes it by a fraction of order (k a)^2 (the theory is linear).
    /// </para>
    /// <para>
    /// Decay: the laminar damping Keulegan derived ("Energy dissipation in standing waves in rectangular basins", J. Fluid
    /// Mech. 6, 1959), by the energy method of <see cref="InternalSeiche"/> with one layer and no interface: the mode's
    /// potential flow slips along the floor and the four walls, each slip taken up in a Stokes layer, and the interior adds
    /// mu k^3 A^2 L W sinh(2 k h) / 2; the mode holds E = rho g a^2 L W / 4.
    /// </para>
    /// <para>
    /// That energy method is the first order in epsilon = nu k^2 / omega: it takes the flow as potential and its strain as
    /// the whole loss. The exact linear mode (<see cref="ViscousMode"/>) adds the vortical layer a free surface needs to
    /// carry no shear stress, sqrt(2 nu / omega) thick, and decays at 2 nu k^2 (1 - sqrt(epsilon / 2) + ...): at 20 Pa s in
    /// RestingTank the layer is as thick as the wave's strain is deep, and the wave decays at 0.72 of 2 nu k^2.
    /// </para>
    /// </summary>
    internal static class SurfaceSeiche
    {
        /// <summary>The fundamental mode's angular frequency, rad/s; <paramref name="mode"/> n is the standing wave with n
        /// half wavelengths along the tank, k = n pi / L.</summary>
        internal static double AngularFrequency(double length, double depth, double gravity, int mode = 1)
        {
            double k = mode * Math.PI / length;
            return Math.Sqrt(gravity * k * Math.Tanh(k * depth));
        }

        /// <summary>The fraction by which omega^2 exceeds g k tanh(k h) when the liquid is a lattice whose two shear
        /// moduli grow with the hydrostatic pressure, C44 = <paramref name="axisModulusRatio"/> p and C' =
        /// <paramref name="diagonalModulusRatio"/> p (<see cref="SphFluid.Simulation.LatticeStability.ShearModulusRatio"/>),
        /// as an SPH lattice's do. The mode's potential flow strains the lattice (its displacement potential
        /// psi = (a / k) cosh(k (z + h)) / sinh(k h) cos(k x)); the strain along the axes, psi_xx = -psi_zz, is resisted
        /// by C' and grows as cosh(k (z + h)), the shear psi_xz by C44 and grows as sinh. With p = rho g (-z) the strain
        /// energy, integrated over the depth, against the mode's potential energy rho g a^2 / 4 (Rayleigh's quotient,
        /// the mode's shape unchanged) is
        ///   c' + c44 + (c' - c44) (k h / sinh(k h))^2:
        /// the same fraction for every mode in deep water, since the moduli grow with depth as fast as the strain
        /// decays, whatever the spacing.</summary>
        internal static double ElasticExcess(double k, double depth, double axisModulusRatio, double diagonalModulusRatio)
        {
            double shallow = k * depth / Math.Sinh(k * depth);
            return diagonalModulusRatio + axisModulusRatio + (diagonalModulusRatio - axisModulusRatio) * shallow * shallow;
        }

        /// <summary>The amplitude's laminar decay rate gamma, 1/s (amplitude ~ exp(-gamma t)), for a liquid of
        /// <paramref name="density"/> kg/m^3 and dynamic <paramref name="viscosity"/> Pa s; free-slip walls
        /// (<paramref name="noSlipWalls"/> false) take no Stokes layer.</summary>
        internal static double DecayRate(double length, double width, double depth, double gravity, double density, double viscosity, bool noSlipWalls)
        {
            double omega = AngularFrequency(length, depth, gravity), k = Math.PI / length, L = length, W = width, h = depth;
            double beta = Math.Sqrt(viscosity * density * omega / 2);
            double a = omega / (k * Math.Sinh(k * h)); // the potential's amplitude per unit surface amplitude
            double floor = L * W / 2 * Math.Pow(omega / Math.Sinh(k * h), 2);
            double walls = noSlipWalls ? 0.5 * beta * (floor + InternalSeiche.EndWalls(W, a, k, h) + InternalSeiche.SideWalls(L, a, k, h)) : 0;
            double dissipation = walls + viscosity * Math.Pow(k, 3) * a * a * L * W * Math.Sinh(2 * k * h) / 2;
            double energy = gravity * density * L * W / 4;
            return dissipation / (2 * energy);
        }

        /// <summary>
        /// The standing wave's exact linear mode in a liquid of kinematic viscosity <paramref name="kinematicViscosity"/>
        /// m^2/s, depth h, between free-slip walls and over a free-slip floor: the amplitude goes as exp(-Gamma t) cos(Omega t).
        /// <para>
        /// Lamb's construction ("Hydrodynamics", art. 349), carried to a finite depth: the velocity is the gradient of
        /// phi = A cosh(k (z + h)) cos(k x) plus the curl of psi = B sinh(m (z + h)) sin(k x), both as exp(s t), with
        /// m^2 = k^2 + s / nu so that psi diffuses. Each part alone meets the floor (no normal velocity, no shear stress)
        /// and the walls, so the free surface's two conditions, no shear stress and the normal stress -p + 2 mu w_z = 0
        /// with the kinematic condition, give s as the root of
        ///   s^2 + 2 nu k^2 s + g k T - 2 k^2 T (g k + 2 nu k m s coth(m h)) / (2 k^2 + s / nu) = 0,   T = tanh(k h),
        /// which in deep water is Lamb's (s + 2 nu k^2)^2 + g k = 4 nu^2 k^3 m. The root is taken by Newton's method from
        /// the energy method's -2 nu k^2 + i omega; m is the root with a positive real part, so psi dies away from the surface.
        /// </para>
        /// </summary>
        internal static (double Gamma, double Omega) ViscousMode(double length, double depth, double gravity, double kinematicViscosity, int mode = 1)
        {
            if (!(kinematicViscosity > 0)) throw new ArgumentOutOfRangeException(nameof(kinematicViscosity), kinematicViscosity, "must be positive");
            double k = mode * Math.PI / length, nu = kinematicViscosity, T = Math.Tanh(k * depth);
            Complex Residual(Complex s)
            {
                var m = Complex.Sqrt(k * k + s / nu);
                // coth(m h) from exp(-2 m h), which stays finite where cosh and sinh would overflow.
                var e = Complex.Exp(-2 * m * depth);
                var coth = (1 + e) / (1 - e);
                return s * s + 2 * nu * k * k * s + gravity * k * T - 2 * k * k * T * (gravity * k + 2 * nu * k * m * s * coth) / (2 * k * k + s / nu);
            }
            var root = new Complex(-2 * nu * k * k, AngularFrequency(length, depth, gravity, mode));
            for (int i = 0; i < 100; i++)
            {
                var h = 1e-7 * Complex.Abs(root);
                var f = Residual(root);
                var next = root - f * h / (Residual(root + h) - f);
                bool settled = Complex.Abs(next - root) <= 1e-12 * Complex.Abs(root);
                root = next;
                if (settled) return (-root.Real, root.Imaginary);
            }
            throw new InvalidOperationException($"no viscous mode found for nu = {nu} m^2/s, k = {k} /m, h = {depth} m");
        }
    }
}
