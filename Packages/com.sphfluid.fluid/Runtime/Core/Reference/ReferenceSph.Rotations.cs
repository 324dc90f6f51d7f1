using SphFluid.Simulation;

namespace SphFluid.Reference
{
    public sealed partial class ReferenceSph
    {
        /// <summary>Each particle's rigid rotation Omega = curl v / 2 for the strain rate's viscous stress
        /// (SphVelocityGradient.hlsl, FluidSolver's Rotations): the velocity gradient corrected by the inverse of the moment
        /// matrix where its determinant exceeds 0.05, walls with friction counted at their own velocity.</summary>
        Double3[] Rotations(Particle[] particles, Double3[] x, Double3[] v, BoundaryParticle[] walls, Double3[] xb,
            double[] numberDensity, double friction)
        {
            int n = particles.Length;
            var rotations = new Double3[n];
            for (int i = 0; i < n; i++)
            {
                var velocitySum = new double[3, 3];
                var moment = new double[3, 3];
                for (int j = 0; j < n; j++)
                {
                    if (j == i) continue;
                    var rij = x[i] - x[j];
                    double r2 = rij.LengthSquared();
                    if (r2 >= _h2) continue;
                    var gradient = PairGradient(rij, System.Math.Sqrt(r2), particles[i].Id, particles[j].Id) / numberDensity[j];
                    AddGradientPair(velocitySum, moment, v[j] - v[i], rij, gradient);
                }
                for (int b = 0; b < walls.Length; b++)
                {
                    var rib = x[i] - xb[b];
                    double r2 = rib.LengthSquared();
                    if (r2 >= _h2) continue;
                    var gradient = PairGradient(rib, System.Math.Sqrt(r2), 1, 0) * (friction * WallWeight(walls[b], particles[i]) / numberDensity[i]);
                    AddGradientPair(velocitySum, moment, new Double3(walls[b].Velocity) - v[i], rib, gradient);
                }
                rotations[i] = RotationOf(velocitySum, moment);
            }
            return rotations;
        }

        static void AddGradientPair(double[,] velocitySum, double[,] moment, Double3 dv, Double3 rij, Double3 gradient)
        {
            for (int a = 0; a < 3; a++)
            for (int c = 0; c < 3; c++)
            {
                velocitySum[a, c] += dv[a] * gradient[c];
                moment[a, c] -= rij[a] * gradient[c];
            }
        }

        static Double3 RotationOf(double[,] velocitySum, double[,] moment)
        {
            double det = moment[0, 0] * (moment[1, 1] * moment[2, 2] - moment[1, 2] * moment[2, 1])
                       - moment[0, 1] * (moment[1, 0] * moment[2, 2] - moment[1, 2] * moment[2, 0])
                       + moment[0, 2] * (moment[1, 0] * moment[2, 1] - moment[1, 1] * moment[2, 0]);
            var inverse = new double[3, 3] { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
            if (det > 0.05)
            {
                for (int r = 0; r < 3; r++)
                for (int c = 0; c < 3; c++)
                {
                    // The cofactor of moment[c, r] over the determinant.
                    int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
                    inverse[r, c] = (moment[r1, c1] * moment[r2, c2] - moment[r1, c2] * moment[r2, c1]) / det;
                }
            }
            var gradient = new double[3, 3];
            for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                for (int k = 0; k < 3; k++) gradient[r, c] += velocitySum[r, k] * inverse[k, c];
            return new Double3(gradient[2, 1] - gradient[1, 2], gradient[0, 2] - gradient[2, 0], gradient[1, 0] - gradient[0, 1]) * 0.5;
        }
    }
}
