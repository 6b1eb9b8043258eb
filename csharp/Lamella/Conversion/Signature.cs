using System;
using System.Security.Cryptography;

namespace Lamella.Conversion
{
    /// <summary>
    /// A fingerprint of a solve's inputs (mesh arrays and parameters), so that a host can tell whether a stored or
    /// running session still belongs to its current inputs (e.g. a Grasshopper document reopened with the same mesh).
    /// </summary>
    public static class Signature
    {
        /// <summary>SHA-256 (hex) over the exact bits of the positions, triangles and parameter values, in order.</summary>
        public static string Of(double[] xyz, int[] triangles, params double[] parameters)
        {
            if (xyz == null) throw new ArgumentNullException(nameof(xyz));
            if (triangles == null) throw new ArgumentNullException(nameof(triangles));
            if (parameters == null) throw new ArgumentNullException(nameof(parameters));
            var bytes = new byte[8 * xyz.Length + 4 * triangles.Length + 8 * parameters.Length + 8];
            Buffer.BlockCopy(xyz, 0, bytes, 0, 8 * xyz.Length);
            Buffer.BlockCopy(triangles, 0, bytes, 8 * xyz.Length, 4 * triangles.Length);
            Buffer.BlockCopy(parameters, 0, bytes, 8 * xyz.Length + 4 * triangles.Length, 8 * parameters.Length);
            // The split point, so that moving values between the arrays changes the fingerprint.
            Buffer.BlockCopy(BitConverter.GetBytes((long)xyz.Length << 32 | (uint)triangles.Length), 0, bytes, bytes.Length - 8, 8);
            using (var sha = SHA256.Create())
            {
                return BitConverter.ToString(sha.ComputeHash(bytes)).Replace("-", "").ToLowerInvariant();
            }
        }
    }
}
