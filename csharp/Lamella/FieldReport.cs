using System.Runtime.InteropServices;

namespace Lamella
{
    /// <summary>
    /// The state of a field optimisation (<c>LmlReport</c>). Energies are those of the normalised problem,
    /// unweighted; angles in degrees.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FieldReport
    {
        /// <summary>Iterations run since the session was created.</summary>
        public ulong Iterations;
        /// <summary>Iterations run by the last step.</summary>
        public ulong IterationsThisStep;
        /// <summary>Index of the weight stage in force.</summary>
        public ulong Stage;
        /// <summary>E_fair (paper Eq. 6).</summary>
        public double EnergyFair;
        /// <summary>E_grad (paper Eq. 11).</summary>
        public double EnergyGrad;
        /// <summary>The curve term: E_angle (Eq. 8), E_geo or E_asy (Eq. 13).</summary>
        public double EnergyAngle;
        /// <summary>The auxiliary-variable constraints of Eq. 9–10.</summary>
        public double EnergyFrame;
        /// <summary>The weighted total being minimised.</summary>
        public double EnergyTotal;
        /// <summary>RMS of |θ_measured − θ| over the measured vertices, degrees.</summary>
        public double AngleErrorRmsDegrees;
        /// <summary>Maximum of |θ_measured − θ| over the measured vertices, degrees.</summary>
        public double AngleErrorMaxDegrees;
        /// <summary>Interior vertices where the angle was measured.</summary>
        public ulong MeasuredVertices;
        /// <summary>Interior vertices whose level curve does not cross exactly two star edges.</summary>
        public ulong SingularVertexCount;
        /// <summary>Side vectors re-oriented during the last step.</summary>
        public ulong Flips;
        /// <summary>Levenberg–Marquardt damping after the last iteration.</summary>
        public double Damping;
        /// <summary>1 when converged (use <see cref="IsConverged"/>).</summary>
        public ulong Converged;

        /// <summary>True when the final stage has converged: further steps do nothing.</summary>
        public bool IsConverged => Converged != 0;

        /// <summary>A multi-line summary for display: iterations, stage, energies, angle errors, singular vertices.</summary>
        public string Describe() =>
            string.Format(System.Globalization.CultureInfo.InvariantCulture,
                "{0}\niterations {1} (last step {2}), stage {3}\nE_fair {4:0.###e+0}, E_grad {5:0.###e+0}, E_angle {6:0.###e+0}, E_frame {7:0.###e+0}, weighted total {8:0.###e+0}\n" +
                "angle error: max {9:0.###}°, rms {10:0.###}° over {11} vertices\nsingular vertices {12}, flips {13}, damping {14:0.###e+0}",
                IsConverged ? "converged" : "not converged", Iterations, IterationsThisStep, Stage, EnergyFair, EnergyGrad, EnergyAngle,
                EnergyFrame, EnergyTotal, AngleErrorMaxDegrees, AngleErrorRmsDegrees, MeasuredVertices, SingularVertexCount, Flips, Damping);

        /// <inheritdoc />
        public override string ToString() =>
            string.Format(System.Globalization.CultureInfo.InvariantCulture,
                "iteration {0}, E_angle {1:0.###e+0}, max angle error {2:0.###}°{3}",
                Iterations, EnergyAngle, AngleErrorMaxDegrees, IsConverged ? ", converged" : "");
    }
}
