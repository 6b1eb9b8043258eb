using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using System.Runtime.InteropServices;
using Lamella.Interop;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>
    /// The binding matches include/lamella.h mechanically: every header function has a [DllImport] with the same
    /// name, parameter count and pointer/value kind (and value size) of each parameter and of the result, and
    /// nothing else is imported; every header struct has a managed twin with the same field offsets and size;
    /// every constant has an enum member with its value. A function or struct added to the C ABI fails here
    /// until the binding covers it.
    /// </summary>
    [TestFixture]
    public class HeaderParityTests
    {
        /// <summary>The managed twin of each C struct; a new C struct must be added here (and bound).</summary>
        private static readonly Dictionary<string, Type> StructTwins = new Dictionary<string, Type>
        {
            { "LmlWeights", typeof(Weights) },
            { "LmlFieldParams", typeof(FieldParams) },
            { "LmlReport", typeof(FieldReport) },
            { "LmlStripWeights", typeof(StripWeights) },
            { "LmlStripParams", typeof(StripParams) },
            { "LmlStripMetrics", typeof(StripMetrics) },
            { "LmlPatternMetrics", typeof(PatternMetrics) },
            { "LmlSkippedCurve", typeof(SkippedCurve) },
            { "LmlEdgePoint", typeof(EdgePoint) },
            { "LmlTraceOptions", typeof(TraceOptions) },
            { "LmlCrossing", typeof(Crossing) },
            { "LmlCandidate", typeof(CandidateRecord) },
            { "LmlVerdict", typeof(VerdictRecord) },
            { "LmlVertexDiagnostics", typeof(VertexDiagnostics) },
            { "LmlMaterial", typeof(Material) },
            { "LmlStock", typeof(Stock) },
            { "LmlStripCheck", typeof(StripCheck) },
            { "LmlPiece", typeof(Piece) },
            { "LmlFabricationSummary", typeof(FabricationSummary) },
            { "LmlNetReport", typeof(NetReportRecord) },
            { "LmlReshapeReport", typeof(ReshapeReportRecord) },
            { "LmlAlternationReport", typeof(AlternationReportRecord) },
            { "LmlBaseMeshReport", typeof(BaseMeshReportRecord) },
            { "LmlBaseMeshNode", typeof(BaseMeshNodeRecord) },
            { "LmlBaseMeshFamilyReport", typeof(BaseMeshFamilyReportRecord) },
            { "LmlBaseMeshWeights", typeof(BaseMeshWeights) },
            { "LmlNode", typeof(NodeRecord) },
            { "LmlWebReport", typeof(WebReportRecord) },
            { "LmlWebNode", typeof(WebNodeRecord) },
            { "LmlShadingSite", typeof(ShadingSite) },
            { "LmlShadingReport", typeof(ShadingReportRecord) },
            { "LmlSunPathSummary", typeof(SunPathSummaryRecord) },
        };

        /// <summary>Integer typedefs of the header and the managed enum each is carried by (also in arrays).</summary>
        private static readonly Dictionary<string, Type> ScalarTypedefs = new Dictionary<string, Type>
        {
            { "LmlStatus", typeof(Status) },
            { "LmlFamily", typeof(Family) },
            { "LmlStripWarnings", typeof(StripWarnings) },
            { "LmlTraceStop", typeof(TraceStop) },
            { "LmlShadingLabel", typeof(ShadingLabel) },
        };

        private static Dictionary<string, MethodInfo> Imports() =>
            typeof(NativeMethods).GetMethods(BindingFlags.Static | BindingFlags.Public | BindingFlags.NonPublic)
                .Where(m => m.GetCustomAttributes(typeof(DllImportAttribute), false).Length > 0)
                .ToDictionary(m => EntryPoint(m), m => m);

        private static string EntryPoint(MethodInfo method)
        {
            var import = (DllImportAttribute)method.GetCustomAttributes(typeof(DllImportAttribute), false)[0];
            return string.IsNullOrEmpty(import.EntryPoint) ? method.Name : import.EntryPoint;
        }

        [Test]
        public void HeaderIsReadable()
        {
            // Guards the parser: the header has dozens of functions and the known structs.
            Assert.Greater(Header.Functions().Count, 40);
            Assert.IsTrue(Header.Functions().Any(f => f.Name == "lml_mesh_new" && f.Parameters.Count == 5));
            Assert.AreEqual(StructTwins.Count, Header.Structs().Count);
        }

        [Test]
        public void EveryHeaderFunctionHasAMatchingImport()
        {
            var imports = Imports();
            var problems = new List<string>();
            foreach (CFunction f in Header.Functions())
            {
                MethodInfo method;
                if (!imports.TryGetValue(f.Name, out method))
                {
                    problems.Add(f.Name + ": no [DllImport] in NativeMethods");
                    continue;
                }
                var import = (DllImportAttribute)method.GetCustomAttributes(typeof(DllImportAttribute), false)[0];
                if (import.CallingConvention != CallingConvention.Cdecl) problems.Add(f.Name + ": not Cdecl");
                if (import.Value != NativeMethods.Library) problems.Add(f.Name + ": imported from " + import.Value);
                ParameterInfo[] parameters = method.GetParameters();
                if (parameters.Length != f.Parameters.Count)
                {
                    problems.Add(f.Name + ": " + f.Parameters.Count + " parameters in C, " + parameters.Length + " in C#");
                    continue;
                }
                for (int i = 0; i < parameters.Length; i++)
                {
                    string mismatch = Mismatch(f.Parameters[i], parameters[i].ParameterType);
                    if (mismatch != null) problems.Add(f.Name + " parameter " + i + " (" + parameters[i].Name + "): " + mismatch);
                }
                string result = Mismatch(f.Return, method.ReturnType);
                if (result != null) problems.Add(f.Name + " result: " + result);
            }
            Assert.IsEmpty(problems, string.Join("\n", problems));
        }

        [Test]
        public void EveryImportIsInTheHeader()
        {
            var names = new HashSet<string>(Header.Functions().Select(f => f.Name));
            CollectionAssert.IsEmpty(Imports().Keys.Where(n => !names.Contains(n)).ToList());
        }

        /// <summary>Null when a C# type can carry the C type: pointers as arrays, by-refs, handles or IntPtr; values of the same size.</summary>
        private static string Mismatch(CType c, Type managed)
        {
            if (c.IsVoid) return managed == typeof(void) ? null : "void in C, " + managed.Name + " in C#";
            bool managedPointer = managed.IsByRef || managed.IsArray || typeof(SafeHandle).IsAssignableFrom(managed) || managed == typeof(IntPtr);
            if (c.IsPointer != managedPointer) return (c.IsPointer ? "pointer" : "value") + " " + c.Text + " in C, " + managed.Name + " in C#";
            if (c.IsPointer) return PointeeMismatch(c, managed);
            int cSize = CSize(c.Base), managedSize = Marshal.SizeOf(managed.IsEnum ? Enum.GetUnderlyingType(managed) : managed);
            return cSize == managedSize ? null : c.Text + " has " + cSize + " bytes, " + managed.Name + " " + managedSize;
        }

        /// <summary>
        /// A pointer to a header struct must be carried by its twin (by reference or as an array); a pointer to an
        /// opaque handle LmlX by the SafeHandle XHandle, or by IntPtr in the _free functions.
        /// </summary>
        private static string PointeeMismatch(CType c, Type managed)
        {
            string name = c.Base.StartsWith("struct ", StringComparison.Ordinal) ? c.Base.Substring(7) : c.Base;
            Type element = managed.IsByRef || managed.IsArray ? managed.GetElementType() : managed;
            Type twin;
            if (StructTwins.TryGetValue(name, out twin))
                return element == twin ? null : c.Text + " in C, " + managed.Name + " in C#";
            if (ScalarTypedefs.TryGetValue(name, out twin))
                return element == twin ? null : c.Text + " in C, " + managed.Name + " in C#";
            if (name.StartsWith("Lml", StringComparison.Ordinal))
                return element.Name == name.Substring(3) + "Handle" || managed == typeof(IntPtr) ? null : c.Text + " in C, " + managed.Name + " in C#";
            return null;
        }

        private static int CSize(string type) => CLayout(type).Size;

        private struct Layout
        {
            public int Size, Align;
            public Layout(int size, int align) { Size = size; Align = align; }
        }

        /// <summary>Size and alignment of a C type of the header on this platform (C struct layout rules).</summary>
        private static Layout CLayout(string type)
        {
            switch (type)
            {
                case "uint8_t": return new Layout(1, 1);
                case "int32_t": case "uint32_t": case "LmlStatus": case "LmlFamily": case "LmlTraceStop": case "LmlShadingLabel": return new Layout(4, 4);
                case "int64_t": case "uint64_t": case "double": case "LmlStripWarnings": return new Layout(8, 8);
                case "size_t": return new Layout(IntPtr.Size, IntPtr.Size);
            }
            string name = type.StartsWith("struct ", StringComparison.Ordinal) ? type.Substring(7) : type;
            List<CField> fields;
            if (!Header.Structs().TryGetValue(name, out fields)) throw new NotSupportedException("unknown C type " + type + ": teach the test its size");
            int offset = 0, align = 1;
            foreach (CField field in fields)
            {
                Layout f = CLayout(field.Type.Base);
                offset = (offset + f.Align - 1) / f.Align * f.Align + f.Size * field.Count;
                align = Math.Max(align, f.Align);
            }
            return new Layout((offset + align - 1) / align * align, align);
        }

        [Test]
        public void EveryHeaderStructHasATwinWithTheSameLayout()
        {
            var problems = new List<string>();
            foreach (var s in Header.Structs())
            {
                Type twin;
                if (!StructTwins.TryGetValue(s.Key, out twin))
                {
                    problems.Add(s.Key + ": no managed twin");
                    continue;
                }
                FieldInfo[] fields = twin.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic);
                if (fields.Length != s.Value.Count)
                {
                    problems.Add(s.Key + ": " + s.Value.Count + " fields in C, " + fields.Length + " in " + twin.Name);
                    continue;
                }
                int offset = 0;
                for (int i = 0; i < fields.Length; i++)
                {
                    Layout f = CLayout(s.Value[i].Type.Base);
                    offset = (offset + f.Align - 1) / f.Align * f.Align;
                    if (Header.Pascal(s.Value[i].Name.ToUpperInvariant()) != fields[i].Name)
                        problems.Add(s.Key + "." + s.Value[i].Name + " is " + twin.Name + "." + fields[i].Name);
                    if ((int)Marshal.OffsetOf(twin, fields[i].Name) != offset)
                        problems.Add(s.Key + "." + s.Value[i].Name + " at " + offset + " in C, " + Marshal.OffsetOf(twin, fields[i].Name) + " in C#");
                    offset += f.Size * s.Value[i].Count;
                }
                if (Marshal.SizeOf(twin) != CLayout(s.Key).Size)
                    problems.Add(s.Key + ": " + CLayout(s.Key).Size + " bytes in C, " + Marshal.SizeOf(twin) + " in C#");
            }
            Assert.IsEmpty(problems, string.Join("\n", problems));
        }

        [Test]
        public void ConstantsMatchTheEnums()
        {
            AssertEnumMatches(typeof(Status), Header.ConstantsPascal("LML_STATUS_"));
            AssertEnumMatches(typeof(Family), Header.ConstantsPascal("LML_FAMILY_"));
            var warnings = Header.ConstantsPascal("LML_STRIP_WARNING_");
            warnings["None"] = 0;
            AssertEnumMatches(typeof(StripWarnings), warnings);
            AssertEnumMatches(typeof(TraceStop), Header.ConstantsPascal("LML_TRACE_STOP_"));
            AssertEnumMatches(typeof(StartKind), Header.ConstantsPascal("LML_START_"));
            AssertEnumMatches(typeof(FabricationText), Header.ConstantsPascal("LML_FABRICATION_TEXT_"));
            AssertEnumMatches(typeof(ShadingLabel), Header.ConstantsPascal("LML_SHADING_"));
            AssertEnumMatches(typeof(DiagnosticParts), Header.ConstantsPascal("LML_DIAGNOSTIC_"));
            Assert.AreEqual(Header.FloatConstants()["LML_DEFAULT_CORNER_TURN_DEGREES"], BoundaryStarts.DefaultCornerTurnDegrees);
            Assert.AreEqual(Header.Constants()["LML_ABI_VERSION"], (long)Library.BindingAbiVersion);
        }

        private static void AssertEnumMatches(Type type, Dictionary<string, long> expected)
        {
            var actual = Enum.GetNames(type).ToDictionary(n => n, n => Convert.ToInt64(Enum.Parse(type, n)));
            CollectionAssert.AreEquivalent(expected, actual, type.Name);
        }

        [Test]
        public void LoadedLibraryImplementsTheHeadersAbi()
        {
            Assert.AreEqual(Library.BindingAbiVersion, Library.AbiVersion);
            Assert.DoesNotThrow(Library.CheckAbiVersion);
            StringAssert.IsMatch(@"^\d+\.\d+\.\d+", Library.Version);
            foreach (Status status in Enum.GetValues(typeof(Status)))
            {
                // Independent of the library: the C name is LML_STATUS_ + the member in SCREAMING_SNAKE_CASE.
                string screaming = System.Text.RegularExpressions.Regex.Replace(status.ToString(), "(?<=[A-Za-z])([A-Z])", "_$1").ToUpperInvariant();
                Assert.AreEqual("LML_STATUS_" + screaming, Library.StatusName(status));
            }
            Assert.AreEqual("LML_STATUS_UNKNOWN", Library.StatusName((Status)12345));
        }
    }
}
