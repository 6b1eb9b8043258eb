using System;
using System.Collections.Generic;
using System.IO;

namespace Lamella.Hosting
{
    /// <summary>
    /// What a host document keeps of a field session: the field values (what cannot be recomputed), the θ and
    /// parameters it was solved with, its last report, and the signature of the inputs it belongs to. About 8 bytes per
    /// vertex before compression, against ~100 for a whole session (which also holds a copy of the mesh, the auxiliary
    /// binormals and side vectors, and the solver state).
    /// </summary>
    public sealed class SavedField
    {
        /// <summary>Captures a field.</summary>
        public SavedField(int iteration, string signature, double thetaDegrees, FieldParams parameters, FieldReport report, double[] values)
        {
            if (iteration < 0) throw new ArgumentOutOfRangeException(nameof(iteration));
            Iteration = iteration;
            Signature = signature ?? throw new ArgumentNullException(nameof(signature));
            ThetaDegrees = thetaDegrees;
            Parameters = parameters;
            Report = report;
            Values = values ?? throw new ArgumentNullException(nameof(values));
        }

        /// <summary>The host iteration (data-tree item) the field belongs to.</summary>
        public int Iteration { get; }
        /// <summary>The fingerprint of the inputs it was solved from (see <see cref="Conversion.Signature"/>).</summary>
        public string Signature { get; }
        /// <summary>The θ it was solved for, in degrees.</summary>
        public double ThetaDegrees { get; }
        /// <summary>The parameters the session was started with.</summary>
        public FieldParams Parameters { get; }
        /// <summary>The session's report when it was saved.</summary>
        public FieldReport Report { get; }
        /// <summary>The field, one value per vertex of the mesh it was solved on.</summary>
        public double[] Values { get; }
    }

    /// <summary>
    /// The byte format of saved fields: "LMLA", a format version, then Deflate-compressed records. Field values are
    /// stored byte plane by byte plane (all first bytes, then all second bytes, …), which lets Deflate find the
    /// repetition in the sign, exponent and leading mantissa bytes of a smooth field.
    /// </summary>
    public static class FieldArchive
    {
        private const string Magic = "LMLA";
        /// <summary>The format version written (2: the parameters carry the slope axis). Version 1 is read too.</summary>
        public const int Version = 2;
        private const int MaxValues = 1 << 28;

        /// <summary>The fields as bytes.</summary>
        public static byte[] Write(IList<SavedField> fields)
        {
            if (fields == null) throw new ArgumentNullException(nameof(fields));
            return ArchiveFraming.Write(Magic, Version, writer =>
            {
                writer.Write(fields.Count);
                foreach (SavedField field in fields)
                {
                    if (field == null) throw new ArgumentException("a saved field is null", nameof(fields));
                    writer.Write(field.Iteration);
                    writer.Write(field.Signature);
                    writer.Write(field.ThetaDegrees);
                    WriteParams(writer, field.Parameters);
                    WriteReport(writer, field.Report);
                    writer.Write(field.Values.Length);
                    writer.Write(Shuffle(field.Values));
                }
            });
        }

        /// <summary>
        /// Reads fields written by <see cref="Write"/>. Bytes of another kind, another version, truncated or damaged
        /// throw <see cref="FormatException"/> saying which.
        /// </summary>
        public static List<SavedField> Read(byte[] bytes) => ArchiveFraming.Read(bytes, Magic, 1, Version, "saved Lamella fields", (reader, version) =>
        {
            int count = reader.ReadInt32();
            if (count < 0 || count > 1 << 20) throw new FormatException("the saved fields claim " + count + " entries");
            var fields = new List<SavedField>(Math.Min(count, 1024));
            for (int i = 0; i < count; i++)
            {
                int iteration = reader.ReadInt32();
                string signature = reader.ReadString();
                double theta = reader.ReadDouble();
                FieldParams parameters = ReadParams(reader, version);
                FieldReport report = ReadReport(reader);
                int n = reader.ReadInt32();
                if (n < 0 || n > MaxValues) throw new FormatException("saved field " + i + " claims " + n + " values");
                byte[] planes = reader.ReadBytes(8 * n);
                if (planes.Length != 8 * n) throw new FormatException("saved field " + i + " is truncated");
                if (iteration < 0) throw new FormatException("saved field " + i + " has iteration " + iteration);
                fields.Add(new SavedField(iteration, signature, theta, parameters, report, Unshuffle(planes, n)));
            }
            return fields;
        });

        private static byte[] Shuffle(double[] values)
        {
            int n = values.Length;
            var raw = new byte[8 * n];
            Buffer.BlockCopy(values, 0, raw, 0, raw.Length);
            var planes = new byte[raw.Length];
            for (int i = 0; i < n; i++)
            {
                for (int b = 0; b < 8; b++) planes[b * n + i] = raw[8 * i + b];
            }
            return planes;
        }

        private static double[] Unshuffle(byte[] planes, int n)
        {
            var raw = new byte[8 * n];
            for (int i = 0; i < n; i++)
            {
                for (int b = 0; b < 8; b++) raw[8 * i + b] = planes[b * n + i];
            }
            var values = new double[n];
            Buffer.BlockCopy(raw, 0, values, 0, raw.Length);
            return values;
        }

        private static void WriteParams(BinaryWriter w, FieldParams p)
        {
            w.Write((uint)p.Family);
            w.Write(p.WarmUp);
            w.Write(p.ThetaDegrees);
            w.Write(p.Weights.Fair);
            w.Write(p.Weights.Grad);
            w.Write(p.Weights.Angle);
            w.Write(p.GradientTarget);
            w.Write(p.RelativeTolerance);
            double[] axis = p.SlopeAxis ?? DefaultSlopeAxis;
            for (int k = 0; k < 3; k++) w.Write(axis[k]);
        }

        /// <summary>The library's default slope axis, that of version 1 archives.</summary>
        private static readonly double[] DefaultSlopeAxis = { 0.0, 0.0, 1.0 };

        private static FieldParams ReadParams(BinaryReader r, int version) => new FieldParams
        {
            Family = (Family)r.ReadUInt32(),
            WarmUp = r.ReadUInt32(),
            ThetaDegrees = r.ReadDouble(),
            Weights = new Weights(r.ReadDouble(), r.ReadDouble(), r.ReadDouble()),
            GradientTarget = r.ReadDouble(),
            RelativeTolerance = r.ReadDouble(),
            SlopeAxis = version >= 2 ? new[] { r.ReadDouble(), r.ReadDouble(), r.ReadDouble() } : (double[])DefaultSlopeAxis.Clone(),
        };

        private static void WriteReport(BinaryWriter w, FieldReport r)
        {
            foreach (ulong v in new[] { r.Iterations, r.IterationsThisStep, r.Stage, r.MeasuredVertices, r.SingularVertexCount, r.Flips, r.Converged }) w.Write(v);
            foreach (double v in new[] { r.EnergyFair, r.EnergyGrad, r.EnergyAngle, r.EnergyFrame, r.EnergyTotal, r.AngleErrorRmsDegrees, r.AngleErrorMaxDegrees, r.Damping }) w.Write(v);
        }

        private static FieldReport ReadReport(BinaryReader r)
        {
            var report = new FieldReport
            {
                Iterations = r.ReadUInt64(),
                IterationsThisStep = r.ReadUInt64(),
                Stage = r.ReadUInt64(),
                MeasuredVertices = r.ReadUInt64(),
                SingularVertexCount = r.ReadUInt64(),
                Flips = r.ReadUInt64(),
                Converged = r.ReadUInt64(),
            };
            report.EnergyFair = r.ReadDouble();
            report.EnergyGrad = r.ReadDouble();
            report.EnergyAngle = r.ReadDouble();
            report.EnergyFrame = r.ReadDouble();
            report.EnergyTotal = r.ReadDouble();
            report.AngleErrorRmsDegrees = r.ReadDouble();
            report.AngleErrorMaxDegrees = r.ReadDouble();
            report.Damping = r.ReadDouble();
            return report;
        }
    }
}
