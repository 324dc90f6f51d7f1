using System;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Whether a fluid at rest can stay at rest: the linear stability of the spawn lattice (simple cubic, spacing s)
    /// under a uniform pressure p, for the solver's symmetric pressure force
    /// F_i = -sum_j (p_i / delta_i^2 + p_j / delta_j^2) gradW(r_ij) (Shaders/Include/SphPressureForce.hlsl).
    /// <para>
    /// Displace every particle by a wave u_j = a exp(i k . r_j). To first order the force on a particle of mass
    /// m = rho0 / delta0 is
    ///   m u'' = -[ P' S S^T + 2 (p / delta0^2) K(k) ] a,
    ///   S(k) = sum_j gradW(r_j) sin(k . r_j),    K(k) = sum_j HessW(r_j) (1 - cos(k . r_j)),
    /// summed over the lattice points r_j != 0 within the support. The first term is the acoustic stiffness: the
    /// density change the wave makes, priced by the equation of state (P' grows with the Tait stiffness). It acts
    /// along S only. Across S only the second term acts, the pressure pre-stressing the lattice, and where K has a
    /// negative eigenvalue lambda there the wave grows at
    ///   sigma = sqrt(-2 p lambda / (rho0 delta0)),
    /// whatever the stiffness and the time step, and as the square root of the pressure: in a tank, of g and the depth.
    /// That is the tensile-instability analysis of Swegle, Hicks and Attaway ("Smoothed particle hydrodynamics stability
    /// analysis", 1995), done for the 3-D lattice in compression instead of one dimension in tension. Whether lambda
    /// is negative hangs on which neighbour shells fall where in the kernel: for the cubic spline at 2 spacings it is,
    /// for Wendland C2 at 2.8 to 2.9 spacings it is not.
    /// </para>
    /// <para>
    /// The analysis sees a perfect lattice far from walls and surfaces; dissipation (artificial and physical
    /// viscosity) damps slow growth. It agrees with the resting tank (RestingTankTests, TankEquilibriumProbe): the
    /// cubic spline at 2 spacings, predicted to grow at about 25/s at the tank's mid-depth pressure, was measured
    /// growing at 17/s; Wendland C2 at 3 and 4 spacings, predicted at 4.1/s and 2.4/s, was measured decaying.
    /// </para>
    /// </summary>
    public static class LatticeStability
    {
        /// <summary>Wave vectors sampled per axis over [0, pi / s]: the cubic lattice's zone, by symmetry.</summary>
        const int Samples = 16;

        /// <summary>lambda / delta0 (1/m^2), the most negative eigenvalue of K(k) across S(k) over the zone, per unit
        /// number density; 0 where the lattice is stable under pressure.</summary>
        public static double SoftestMode(KernelFamily kind, double spacing, double support)
        {
            var neighbours = Neighbours(kind, spacing, support);
            double softest = LatticeZone.Smallest(Samples, 0.0,
                (a, b, c) => TransverseEigenvalue(neighbours, (float)(Math.PI / spacing / Samples) * new Vector3(a, b, c)));
            return softest / SmoothingKernels.LatticeNumberDensity(kind, spacing, support);
        }

        /// <summary>sigma (1/s), how fast the lattice's softest wave grows at pressure <paramref name="pressure"/> (Pa) in a
        /// fluid of rest density <paramref name="restDensity"/>; 0 where the lattice is stable.</summary>
        public static double GrowthRate(KernelFamily kind, double spacing, double support, double pressure, double restDensity) =>
            Math.Sqrt(Math.Max(0.0, -2.0 * pressure / restDensity * SoftestMode(kind, spacing, support)));

        /// <summary>G / p: the lattice's shear modulus under pressure p, per unit pressure, for a long shear wave travelling
        /// along <paramref name="direction"/> that moves the particles along <paramref name="polarisation"/> (unit vectors,
        /// normal to each other). It is K(k)'s long-wave limit, K ~ (1/2) sum_j HessW(r_j) (k . r_j)^2, read as an elastic
        /// stiffness, rho0 omega^2 = G k^2, and it depends only on the kernel and the support in spacings. A cubic lattice
        /// has two: along an axis, moving along another (x, y), C44, which resists a slip of one lattice plane over the
        /// next (<see cref="LatticeShearStrength"/>'s stiffness at zero slip, for a short support); along a face diagonal,
        /// moving along the other ((1, 1, 0), (1, -1, 0)), C' = (C11 - C12) / 2, which resists stretching along one axis
        /// while shrinking along another. A fluid has neither; where the pressure grows with depth, so do both.</summary>
        public static double ShearModulusRatio(KernelFamily kind, double spacing, double support, Vector3 direction, Vector3 polarisation)
        {
            double sum = 0.0;
            foreach (var n in Neighbours(kind, spacing, support))
            {
                double along = Vector3.Dot(direction, n.Offset), across = Vector3.Dot(polarisation, n.Offset);
                double hessian = (n.Radial - n.Tangential) * across * across / n.Offset.LengthSquared() + n.Tangential;
                sum += hessian * along * along;
            }
            return sum / SmoothingKernels.LatticeNumberDensity(kind, spacing, support);
        }

        readonly struct Neighbour
        {
            public readonly Vector3 Offset, Gradient;
            public readonly double Radial, Tangential;   // HessW = Radial e e^T + Tangential (I - e e^T)

            public Neighbour(Vector3 offset, Vector3 gradient, double radial, double tangential)
            {
                Offset = offset;
                Gradient = gradient;
                Radial = radial;
                Tangential = tangential;
            }
        }

        static Neighbour[] Neighbours(KernelFamily kind, double spacing, double support)
        {
            var list = new System.Collections.Generic.List<Neighbour>();
            SmoothingKernels.ForEachLatticePoint(spacing, support, (x, y, z) =>
            {
                double r = Math.Sqrt(x * x + y * y + z * z);
                if (r <= 0.0 || r >= support) return;
                double first = SmoothingKernels.Derivative(kind, r, support);
                var e = new Vector3((float)(x / r), (float)(y / r), (float)(z / r));
                list.Add(new Neighbour(new Vector3((float)x, (float)y, (float)z), (float)first * e,
                    SmoothingKernels.SecondDerivative(kind, r, support), first / r));
            });
            return list.ToArray();
        }

        /// <summary>The smallest eigenvalue of K(k) in the plane normal to S(k), or of all of K where S vanishes (there the
        /// wave changes no density and nothing but the pressure's term acts).</summary>
        static double TransverseEigenvalue(Neighbour[] neighbours, Vector3 k)
        {
            double kxx = 0, kyy = 0, kzz = 0, kxy = 0, kxz = 0, kyz = 0, sx = 0, sy = 0, sz = 0;
            foreach (var n in neighbours)
            {
                double phase = Vector3.Dot(k, n.Offset), weight = 1.0 - Math.Cos(phase), sin = Math.Sin(phase);
                double r2 = n.Offset.LengthSquared();
                double ex = n.Offset.X, ey = n.Offset.Y, ez = n.Offset.Z;
                double radial = weight * (n.Radial - n.Tangential) / r2, iso = weight * n.Tangential;
                kxx += radial * ex * ex + iso;
                kyy += radial * ey * ey + iso;
                kzz += radial * ez * ez + iso;
                kxy += radial * ex * ey;
                kxz += radial * ex * ez;
                kyz += radial * ey * ez;
                sx += sin * n.Gradient.X;
                sy += sin * n.Gradient.Y;
                sz += sin * n.Gradient.Z;
            }
            var K = new double[3, 3] { { kxx, kxy, kxz }, { kxy, kyy, kyz }, { kxz, kyz, kzz } };
            double sLength = Math.Sqrt(sx * sx + sy * sy + sz * sz), scale = Math.Abs(kxx) + Math.Abs(kyy) + Math.Abs(kzz);
            if (sLength * sLength <= 1e-12 * scale * scale) return SmallestEigenvalue3(K);

            // An orthonormal pair (e1, e2) normal to S, and K's 2 x 2 block in it.
            var s = new[] { sx / sLength, sy / sLength, sz / sLength };
            var helper = Math.Abs(s[0]) < 0.9 ? new[] { 1.0, 0.0, 0.0 } : new[] { 0.0, 1.0, 0.0 };
            var e1 = Normalised(Cross(s, helper));
            var e2 = Cross(s, e1);
            double a = Quadratic(K, e1, e1), d = Quadratic(K, e2, e2), b = Quadratic(K, e1, e2);
            return 0.5 * (a + d) - Math.Sqrt(0.25 * (a - d) * (a - d) + b * b);
        }

        static double Quadratic(double[,] m, double[] u, double[] v)
        {
            double sum = 0;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) sum += u[i] * m[i, j] * v[j];
            return sum;
        }

        static double[] Cross(double[] u, double[] v) =>
            new[] { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };

        static double[] Normalised(double[] u)
        {
            double l = Math.Sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
            return new[] { u[0] / l, u[1] / l, u[2] / l };
        }

        /// <summary>The smallest eigenvalue of a symmetric 3 x 3 matrix, in closed form (the roots of its characteristic cubic,
        /// all real, by the trigonometric method).</summary>
        static double SmallestEigenvalue3(double[,] m)
        {
            double p1 = m[0, 1] * m[0, 1] + m[0, 2] * m[0, 2] + m[1, 2] * m[1, 2];
            double q = (m[0, 0] + m[1, 1] + m[2, 2]) / 3.0;
            if (p1 <= 1e-30 * (q * q + 1e-300)) return Math.Min(m[0, 0], Math.Min(m[1, 1], m[2, 2]));
            double p2 = (m[0, 0] - q) * (m[0, 0] - q) + (m[1, 1] - q) * (m[1, 1] - q) + (m[2, 2] - q) * (m[2, 2] - q) + 2.0 * p1;
            double p = Math.Sqrt(p2 / 6.0);
            var b = new double[3, 3];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) b[i, j] = (m[i, j] - (i == j ? q : 0.0)) / p;
            double det = b[0, 0] * (b[1, 1] * b[2, 2] - b[1, 2] * b[2, 1]) - b[0, 1] * (b[1, 0] * b[2, 2] - b[1, 2] * b[2, 0])
                       + b[0, 2] * (b[1, 0] * b[2, 1] - b[1, 1] * b[2, 0]);
            double phi = Math.Acos(Math.Clamp(det / 2.0, -1.0, 1.0)) / 3.0;
            return q + 2.0 * p * Math.Cos(phi + 2.0 * Math.PI / 3.0);
        }
    }
}
