using System;
using System.Linq;
using Vector3 = System.Numerics.Vector3;
using MathNet.Numerics.LinearAlgebra;
using SphFluid.Simulation;

namespace SphFluid.Tests.Physics
{
    /// <summary>
    /// The interface mode of two layers whose particle lattice is an elastic solid under pressure: Lamb's two layers under
    /// a free surface (<see cref="InternalSeiche"/>), with the strain energy the lattice stores, as
    /// <see cref="SurfaceSeiche.ElasticExcess"/> adds it to a surface wave. A surface wave keeps its potential-flow shape to
    /// first order; an interface mode cannot: its potential flow slips along the interface, which one lattice holding both
    /// liquids does not allow, and the lattice's energy outweighs the density step's. So the mode is solved for, its shape
    /// free.
    /// <para>
    /// A displacement along the tank that meets free-slip end walls and floor is, for the fundamental, the stream function
    /// psi = f(y) sin(k x), k = pi / L: xi = (f'(y) sin(k x), -k f(y) cos(k x)), incompressible, f(0) = 0. Per L / 4 of
    /// section, its kinetic energy at unit rate is T = integral rho (f'^2 + k^2 f^2) dy; gravity stores
    /// V_g = k^2 ((rho2 - rho1) g f(d2)^2 + rho1 g f(H)^2) in the interface and the free surface; the cubic lattice, whose
    /// moduli C' = c' p and C44 = c44 p grow with the hydrostatic pressure p(y)
    /// (<see cref="LatticeStability.ShearModulusRatio"/>), stores
    /// V_e = integral p (4 c' k^2 f'^2 + c44 (f'' + k^2 f)^2) dy: the stretch xi_x,x = k f' cos(k x) and the shear
    /// (f'' + k^2 f) sin(k x) / 2 at 2 C' and 2 C44 times their squares. The modes are the stationary points of
    /// (V_g + V_e) / T, lambda = omega^2 (or -s^2 for a growing one): the generalised eigenproblem of those quadratic forms
    /// in f, taken on <c>nodes</c> equal intervals over the depth by finite differences (the floor and the free surface
    /// carry no shear there, so their second differences are left out). The lattice is continuous across the interface:
    /// one lattice holds both liquids, so f and f' are too. Walls are left out.
    /// </para>
    /// <para>
    /// Without a lattice every flow that moves neither the interface nor the surface has lambda = 0, and Lamb's mode is the
    /// one whose displacement is Lamb's potential flow (<see cref="InternalSeiche.InterfaceModeVelocity"/>); with one,
    /// Lamb's shape spreads over several modes, so each mode carries its likeness to it (in the kinetic energy's inner
    /// product) and its share of a kick with Lamb's flow. A growing mode is any with lambda below 0.
    /// </para>
    /// </summary>
    internal static class ElasticInterfaceMode
    {
        /// <summary>The lattice's two shear moduli per unit pressure (<see cref="LatticeStability.ShearModulusRatio"/>): c44
        /// along an axis, c' along a face diagonal. With c44 below 0 the lattice gives way to short shear waves and the
        /// model has no lowest mode.</summary>
        internal static (double Axis, double Diagonal) ModulusRatios(KernelFamily kind, double spacing, double support) => (
            LatticeStability.ShearModulusRatio(kind, spacing, support, Vector3.UnitX, Vector3.UnitY),
            LatticeStability.ShearModulusRatio(kind, spacing, support, Vector3.Normalize(new Vector3(1, 1, 0)), Vector3.Normalize(new Vector3(1, -1, 0))));

        /// <summary>One mode: lambda = omega^2 (rad/s)^2, negative for a growing mode (-s^2); the cosine of its angle to
        /// Lamb's potential-flow mode in the kinetic energy's inner product (1: the same shape); and its share of a kick, the
        /// interface velocity it takes when the layers are given Lamb's flow at a unit interface velocity (the shares sum to
        /// 1).</summary>
        internal sealed record Mode(double Lambda, double Likeness, double Share);

        /// <summary>Every mode of the fundamental, lowest lambda first.</summary>
        internal static Mode[] Modes(InternalSeiche.Tank t, double axisModulusRatio, double diagonalModulusRatio, int nodes = 240)
        {
            double depth = t.LowerDepth + t.UpperDepth, h = depth / nodes, k = Math.PI / t.Length, g = t.Gravity;
            int interfaceNode = (int)Math.Round(t.LowerDepth / h);
            var kinetic = Matrix<double>.Build.Dense(nodes, nodes);
            var potential = Matrix<double>.Build.Dense(nodes, nodes);

            // Unknowns f_1 .. f_nodes (f_0 = 0 on the floor); each term adds weight (a . f)^2 for a row a of node weights.
            void Add(Matrix<double> form, double weight, params (int Node, double Coefficient)[] row)
            {
                foreach (var (i, a) in row)
                    foreach (var (j, b) in row)
                        if (i > 0 && j > 0) form[i - 1, j - 1] += weight * a * b;
            }
            double Density(double y) => y < t.LowerDepth ? t.LowerDensity : t.UpperDensity;
            double Pressure(double y) => y >= t.LowerDepth
                ? t.UpperDensity * g * (depth - y)
                : t.UpperDensity * g * t.UpperDepth + t.LowerDensity * g * (t.LowerDepth - y);

            for (int i = 0; i < nodes; i++)
            {
                double middle = (i + 0.5) * h, slope = 1 / h;
                Add(kinetic, Density(middle) * h, (i, -slope), (i + 1, slope));
                Add(potential, 4 * diagonalModulusRatio * k * k * Pressure(middle) * h, (i, -slope), (i + 1, slope));
                Add(kinetic, 0.5 * h * Density(middle) * k * k, (i, 1));
                Add(kinetic, 0.5 * h * Density(middle) * k * k, (i + 1, 1));
            }
            for (int i = 1; i < nodes; i++)
            {
                double curvature = 1 / (h * h);
                Add(potential, axisModulusRatio * Pressure(i * h) * h, (i - 1, curvature), (i, k * k - 2 * curvature), (i + 1, curvature));
            }
            Add(potential, k * k * (t.LowerDensity - t.UpperDensity) * g, (interfaceNode, 1));
            Add(potential, k * k * t.UpperDensity * g, (nodes, 1));

            // K f = lambda M f, as the symmetric C = L^-1 K L^-T with M = L L^T.
            var lower = kinetic.Cholesky().Factor;
            var inverse = lower.Inverse();
            var symmetric = inverse * potential * inverse.Transpose();
            symmetric = 0.5 * (symmetric + symmetric.Transpose());
            var evd = symmetric.Evd(Symmetricity.Symmetric);

            // Lamb's shape, f = -xi_y(0, y) / k for a unit interface amplitude.
            double rate = Math.Sqrt(Math.Abs(InternalSeiche.InternalRootSquared(t)));
            var lamb = Vector<double>.Build.Dense(nodes, i => -InternalSeiche.InterfaceModeVelocity(t, 1, 0, (i + 1) * h).Up / rate / k);
            var lambInM = lower.Transpose() * lamb;
            var modes = new Mode[nodes];
            var back = inverse.Transpose();
            for (int m = 0; m < nodes; m++)
            {
                var v = evd.EigenVectors.Column(m);
                v /= v.L2Norm();
                double kick = v.DotProduct(lambInM); // f_m^T M u0 for f_m = L^-T v, M-normalised
                double atInterface = -k * back.Row(interfaceNode - 1).DotProduct(v);
                modes[m] = new Mode(evd.EigenValues[m].Real, Math.Abs(kick) / lambInM.L2Norm(), kick * atInterface);
            }
            return modes.OrderBy(m => m.Lambda).ToArray();
        }

        /// <summary>The interface's amplitude (m) at <paramref name="time"/> after flat layers at rest were given Lamb's flow
        /// for an interface velocity of <paramref name="amplitude"/> times Lamb's rate (<see cref="InternalSeicheProbe.Kick"/>),
        /// each mode moving it by its share times sin(omega t) / omega, or sinh(s t) / s: without a lattice,
        /// amplitude sinh(s t) or amplitude sin(omega t).</summary>
        internal static double KickedInterface(Mode[] modes, InternalSeiche.Tank t, double amplitude, double time)
        {
            double rate = Math.Sqrt(Math.Abs(InternalSeiche.InternalRootSquared(t))), sum = 0;
            foreach (var m in modes)
            {
                double w = Math.Sqrt(Math.Abs(m.Lambda));
                sum += m.Share * (w * time < 1e-9 ? time : m.Lambda > 0 ? Math.Sin(w * time) / w : Math.Sinh(w * time) / w);
            }
            return amplitude * rate * sum;
        }
    }
}
