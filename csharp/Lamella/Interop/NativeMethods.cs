using System;
using System.Runtime.InteropServices;

namespace Lamella.Interop
{
    /// <summary>
    /// The C ABI of include/lamella.h, one declaration per header function, in the header's order
    /// (a test parses the header and compares names, parameter counts and pointer/value kinds).
    /// Conventions: <c>size_t</c> is <see cref="UIntPtr"/>; input arrays are plain arrays (pinned by the
    /// marshaller), output arrays <c>[Out]</c>; handles are <see cref="LamellaHandle"/> subclasses, except in
    /// the <c>_free</c> functions that their <c>ReleaseHandle</c> calls with the raw pointer; strings the
    /// library owns come back as <see cref="IntPtr"/> (never freed by the marshaller).
    /// </summary>
    internal static class NativeMethods
    {
        /// <summary>
        /// The library name: lamella_native.dll, liblamella_native.so, liblamella_native.dylib (see
        /// <see cref="NativeLibraryLoader"/>): cargo's lamella.dll / liblamella.* copied under a name that no file system
        /// confuses with the managed Lamella.dll.
        /// </summary>
        public const string Library = "lamella_native";
        private const CallingConvention Cdecl = CallingConvention.Cdecl;

        // Versions, status names, errors, test hooks.
        [DllImport(Library, CallingConvention = Cdecl)] public static extern uint lml_abi_version();
        [DllImport(Library, CallingConvention = Cdecl)] public static extern IntPtr lml_version();
        [DllImport(Library, CallingConvention = Cdecl)] public static extern IntPtr lml_status_name(int status);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern IntPtr lml_last_error_message();
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_debug_trigger_panic();
        [DllImport(Library, CallingConvention = Cdecl)] public static extern UIntPtr lml_debug_live_handles();

        // LmlMesh.
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_mesh_new_brauner(UIntPtr targetVertices, double mu, out MeshHandle mesh);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_brauner_u_lines(double mu, UIntPtr lines, UIntPtr points, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_mesh_new(double[] xyz, UIntPtr vertexCount, uint[] triangles, UIntPtr triangleCount, out MeshHandle mesh);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_mesh_read_obj(byte[] utf8Path, out MeshHandle mesh);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern void lml_mesh_free(IntPtr mesh);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_mesh_vertex_count(MeshHandle mesh, out UIntPtr count);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_mesh_triangle_count(MeshHandle mesh, out UIntPtr count);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_mesh_positions(MeshHandle mesh, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_mesh_triangles(MeshHandle mesh, [Out] uint[] buffer, UIntPtr capacity, out UIntPtr needed);

        // LmlField.
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_field_params_default(uint family, double thetaDegrees, out FieldParams parameters);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_field_new(MeshHandle mesh, double[] initialField, UIntPtr n, [In] ref FieldParams parameters, out FieldHandle field);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern void lml_field_free(IntPtr field);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_field_step(FieldHandle field, uint maxIterations, out FieldReport report);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_field_solve(FieldHandle field, uint maxIterations, out FieldReport report);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_field_report(FieldHandle field, out FieldReport report);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_field_set_weights(FieldHandle field, Weights weights);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_field_values(FieldHandle field, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_field_binormals(FieldHandle field, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_field_side_vectors(FieldHandle field, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_field_singular_vertices(FieldHandle field, [Out] uint[] buffer, UIntPtr capacity, out UIntPtr needed);

        // LmlSearch (declared between lml_field_singular_vertices and lml_field_save in the header).
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_search_new(MeshHandle mesh, [In] ref FieldParams parameters, out SearchHandle search);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern void lml_search_free(IntPtr search);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_search_step(SearchHandle search);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_search_candidate_count(SearchHandle search, out UIntPtr count);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_search_candidate(SearchHandle search, UIntPtr index, out CandidateRecord candidate);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_search_candidate_text(SearchHandle search, UIntPtr index, [Out] byte[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_search_winner(SearchHandle search, out UIntPtr index);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_search_proxy_vertex_count(SearchHandle search, out UIntPtr count);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_search_field(SearchHandle search, out FieldHandle field);

        // LmlNet.
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_net_new(MeshHandle mesh, double thetaDegreesF, double thetaDegreesG, double[] initialFields, UIntPtr n,
            double minIntersectionDegrees, double intersectionDegrees, out NetHandle net);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_net_start(MeshHandle mesh, double thetaDegreesF, double thetaDegreesG, double minIntersectionDegrees,
            [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern void lml_net_free(IntPtr net);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_net_step(NetHandle net, uint maxIterations, out NetReportRecord report);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_net_report(NetHandle net, out NetReportRecord report);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_net_field(NetHandle net, uint k, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_net_family_count(NetHandle net, out uint count);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_net_save(NetHandle net, [Out] byte[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_net_load(byte[] bytes, UIntPtr length, out NetHandle net);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_curves_new_from_net(NetHandle net, uint k, UIntPtr count, double spacing, out CurvesHandle curves);

        // LmlStripNet.
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_net_new(NetHandle net, StripsHandle stripsF, StripsHandle stripsG, out StripNetHandle stripNet);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern void lml_strip_net_free(IntPtr stripNet);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_net_vertices(StripNetHandle stripNet, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_net_levels(StripNetHandle stripNet, [Out] uint[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_net_quads(StripNetHandle stripNet, [Out] uint[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_net_nodes(StripNetHandle stripNet, [Out] NodeRecord[] buffer, UIntPtr capacity, out UIntPtr needed);

        // 3-webs: LmlNet sessions of three families, their levels and curves; LmlStripWeb.
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_web_new(MeshHandle mesh, double[] thetas, double[] initialFields, UIntPtr n,
            double minIntersectionDegrees, double intersectionDegrees, out NetHandle net);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_net_web_report(NetHandle net, out WebReportRecord report);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_web_levels(NetHandle net, UIntPtr countF, UIntPtr countH, uint kagome, uint k,
            [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_curves_new_from_web(NetHandle net, uint k, UIntPtr countF, UIntPtr countH, uint kagome, double spacing,
            out CurvesHandle curves);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_web_new(NetHandle net, UIntPtr countF, UIntPtr countH, uint kagome,
            StripsHandle stripsF, StripsHandle stripsH, StripsHandle stripsG, out StripWebHandle web);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern void lml_strip_web_free(IntPtr web);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_web_vertices(StripWebHandle web, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_web_vertex_levels(StripWebHandle web, [Out] long[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_web_face_sizes(StripWebHandle web, [Out] uint[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_web_face_vertices(StripWebHandle web, [Out] uint[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_web_polyline_sizes(StripWebHandle web, uint family, [Out] uint[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_web_polyline_vertices(StripWebHandle web, uint family, [Out] uint[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_web_polyline_levels(StripWebHandle web, uint family, [Out] uint[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_web_nodes(StripWebHandle web, [Out] WebNodeRecord[] buffer, UIntPtr capacity, out UIntPtr needed);

        // LmlReshape.
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_reshape_new(MeshHandle mesh, double[] field, UIntPtr n, double thetaDegrees, double tolerance,
            uint toleranceIsFraction, out ReshapeHandle reshape);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern void lml_reshape_free(IntPtr reshape);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_reshape_step(ReshapeHandle reshape, uint maxIterations, out ReshapeReportRecord report);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_reshape_report(ReshapeHandle reshape, out ReshapeReportRecord report);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_reshape_positions(ReshapeHandle reshape, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_reshape_deviations(ReshapeHandle reshape, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_reshape_save(ReshapeHandle reshape, [Out] byte[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_reshape_load(byte[] bytes, UIntPtr length, out ReshapeHandle reshape);

        // LmlAlternation.
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_alternation_new(MeshHandle mesh, double[] field, UIntPtr n, double thetaDegrees, double tolerance,
            uint toleranceIsFraction, uint iterationsPerStep, out AlternationHandle alternation);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern void lml_alternation_free(IntPtr alternation);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_alternation_step(AlternationHandle alternation, uint maxRounds, out AlternationReportRecord report);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_alternation_report(AlternationHandle alternation, out AlternationReportRecord report);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_alternation_positions(AlternationHandle alternation, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_alternation_field(AlternationHandle alternation, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_alternation_deviations(AlternationHandle alternation, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);

        // LmlBaseMesh.
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_base_mesh_new(MeshHandle reference, double[] xyz, UIntPtr vertexCount, uint[] polylineVertices,
            UIntPtr polylineVertexCount, uint[] polylineLengths, UIntPtr rowCount, UIntPtr columnCount, double thetaDegreesRows,
            double thetaDegreesColumns, uint torsionFree, out BaseMeshHandle baseMesh);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_base_mesh_new_slopes(MeshHandle reference, double[] xyz, UIntPtr vertexCount, uint[] polylineVertices,
            UIntPtr polylineVertexCount, uint[] polylineLengths, UIntPtr rowCount, UIntPtr columnCount, double slopeDegreesRows,
            double slopeDegreesColumns, double[] axis, out BaseMeshHandle baseMesh);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_base_mesh_from_strip_net(StripNetHandle net, MeshHandle reference, double thetaDegreesRows,
            double thetaDegreesColumns, uint torsionFree, out BaseMeshHandle baseMesh);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_base_mesh_new_web(MeshHandle reference, double[] xyz, UIntPtr vertexCount, uint[] polylineVertices,
            UIntPtr polylineVertexCount, uint[] polylineLengths, UIntPtr rowCount, UIntPtr columnCount, UIntPtr diagonalCount, double[] thetas,
            out BaseMeshHandle baseMesh);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_base_mesh_from_strip_web(StripWebHandle web, MeshHandle reference, double[] thetas, out BaseMeshHandle baseMesh);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern void lml_base_mesh_free(IntPtr baseMesh);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_base_mesh_weights_default(out BaseMeshWeights weights);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_base_mesh_weights(BaseMeshHandle baseMesh, out BaseMeshWeights weights);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_base_mesh_set_weights(BaseMeshHandle baseMesh, ref BaseMeshWeights weights);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_base_mesh_step(BaseMeshHandle baseMesh, uint maxIterations, out BaseMeshReportRecord report);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_base_mesh_report(BaseMeshHandle baseMesh, out BaseMeshReportRecord report);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_base_mesh_initial_report(BaseMeshHandle baseMesh, out BaseMeshReportRecord report);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_base_mesh_positions(BaseMeshHandle baseMesh, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_base_mesh_nodes(BaseMeshHandle baseMesh, [Out] BaseMeshNodeRecord[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_base_mesh_family_count(BaseMeshHandle baseMesh, out uint count);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_base_mesh_family_report(BaseMeshHandle baseMesh, uint k, out BaseMeshFamilyReportRecord report);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_base_mesh_triangles(BaseMeshHandle baseMesh, [Out] uint[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_base_mesh_strips(BaseMeshHandle baseMesh, uint k, double width, double toleranceDegrees, out StripsHandle strips);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_base_mesh_save(BaseMeshHandle baseMesh, [Out] byte[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_base_mesh_load(byte[] bytes, UIntPtr length, out BaseMeshHandle baseMesh);

        // LmlShading.
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_shading_site_default(out ShadingSite site);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_shading_new(MeshHandle mesh, ref ShadingSite site, ShadingLabel[] labels, UIntPtr n, uint ring, out ShadingHandle shading);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_shading_new_from_field(MeshHandle mesh, ref ShadingSite site, ShadingLabel[] labels, UIntPtr n, uint ring, double[] startField, out ShadingHandle shading);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern void lml_shading_free(IntPtr shading);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_shading_step(ShadingHandle shading, uint maxIterations, out ShadingReportRecord report);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_shading_report(ShadingHandle shading, out ShadingReportRecord report);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_shading_field(ShadingHandle shading, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_shading_strips(ShadingHandle shading, uint count, double width, double toleranceDegrees, out StripsHandle strips);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_shading_thetas(ShadingHandle shading, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_shading_evaluate(ShadingHandle shading, StripsHandle strips, double offset, out SunPathSummaryRecord summary);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_shading_vertex_fractions(ShadingHandle shading, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);

        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_field_save(FieldHandle field, [Out] byte[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_field_load(byte[] bytes, UIntPtr length, out FieldHandle field);

        // LmlCurves.
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_curves_new(FieldHandle field, double[] levels, UIntPtr levelCount, double spacing, out CurvesHandle curves);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_curves_new_uniform(FieldHandle field, UIntPtr count, double spacing, out CurvesHandle curves);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern void lml_curves_free(IntPtr curves);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_curves_count(CurvesHandle curves, out UIntPtr count);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_curves_offsets(CurvesHandle curves, [Out] UIntPtr[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_curves_points(CurvesHandle curves, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_curves_normals(CurvesHandle curves, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_curves_levels(CurvesHandle curves, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_curves_closed(CurvesHandle curves, [Out] byte[] buffer, UIntPtr capacity, out UIntPtr needed);

        // LmlStrips.
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strip_params_default(double thetaDegrees, double width, out StripParams parameters);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_new(CurvesHandle curves, [In] ref StripParams parameters, out StripsHandle strips);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern void lml_strips_free(IntPtr strips);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_strips_verdict(StripsHandle strips, out VerdictRecord verdict);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_strips_count(StripsHandle strips, out UIntPtr count);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_point_offsets(StripsHandle strips, [Out] UIntPtr[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_vertex_offsets(StripsHandle strips, [Out] UIntPtr[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_quad_offsets(StripsHandle strips, [Out] UIntPtr[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_vertices(StripsHandle strips, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_quads(StripsHandle strips, [Out] uint[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_centres(StripsHandle strips, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_rulings(StripsHandle strips, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_unrolled_vertices(StripsHandle strips, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_unrolled_centres(StripsHandle strips, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_metrics(StripsHandle strips, [Out] StripMetrics[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_diagnostics(StripsHandle strips, [Out] VertexDiagnostics[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_pattern_metrics(StripsHandle strips, out PatternMetrics metrics);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_skipped(StripsHandle strips, [Out] SkippedCurve[] buffer, UIntPtr capacity, out UIntPtr needed);

        // Guide curves: trace options, boundary start points, LmlGuides.
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_trace_options_default(out TraceOptions options);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_boundary_segment_count(MeshHandle mesh, uint loopIndex, double cornerTurnDegrees, out UIntPtr count);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_boundary_starts(MeshHandle mesh, uint loopIndex, double cornerTurnDegrees, uint segmentIndex, uint count,
            [Out] EdgePoint[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_boundary_start_at(MeshHandle mesh, uint loopIndex, double s, out EdgePoint point);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_boundary_start_nearest(MeshHandle mesh, double[] point, out EdgePoint nearest);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_guides_trace(MeshHandle mesh, EdgePoint[] starts, UIntPtr count, double thetaDegrees, double startAngleDegrees,
            [In] ref TraceOptions options, out GuidesHandle guides);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern void lml_guides_free(IntPtr guides);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_guides_count(GuidesHandle guides, out UIntPtr count);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_guides_offsets(GuidesHandle guides, [Out] UIntPtr[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_guides_points(GuidesHandle guides, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_guides_edge_points(GuidesHandle guides, [Out] EdgePoint[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_guides_stops(GuidesHandle guides, [Out] TraceStop[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_guides_lengths(GuidesHandle guides, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_guides_crossings(GuidesHandle guides, [Out] Crossing[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_guides_check_order(GuidesHandle guides);

        // Initial fields from guides and strokes.
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_field_values_from_guides(MeshHandle mesh, GuidesHandle guides, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed,
            out double gradientTarget);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_field_values_from_slope(MeshHandle mesh, double[] axis, double slopeDegrees, [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_field_slope(FieldHandle field, out double slopeDegrees);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_curves_new_reachable_boundary(MeshHandle mesh, double[] axis, double slopeDegrees, out CurvesHandle curves);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_field_values_from_strokes(MeshHandle mesh, double[] points, UIntPtr pointCount, UIntPtr[] offsets, UIntPtr strokeCount,
            [Out] double[] buffer, UIntPtr capacity, out UIntPtr needed, out double thetaDegrees);

        // LmlFabrication.
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_material_preset(byte[] utf8Name, out Material material);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern Status lml_stock_default(double length, out Stock stock);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_fabrication_new(StripsHandle strips, [In] ref Material material, double thickness, [In] ref Stock stock,
            out FabricationHandle fabrication);
        [DllImport(Library, CallingConvention = Cdecl)] public static extern void lml_fabrication_free(IntPtr fabrication);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_fabrication_summary(FabricationHandle fabrication, out FabricationSummary summary);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_fabrication_strip_checks(FabricationHandle fabrication, [Out] StripCheck[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_fabrication_pieces(FabricationHandle fabrication, [Out] Piece[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_strips_view_html(StripsHandle strips, CurvesHandle curves, double[] utilisation, UIntPtr utilisationCount,
            byte[] utf8Title, [Out] byte[] buffer, UIntPtr capacity, out UIntPtr needed);
        [DllImport(Library, CallingConvention = Cdecl)]
        public static extern Status lml_fabrication_text(FabricationHandle fabrication, uint kind, UIntPtr index, [Out] byte[] buffer, UIntPtr capacity,
            out UIntPtr needed);
    }
}
