using System;

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
    }
}
