/* Designs a theta = 60 degree strip pattern through Lamella's C ABI, step by step.
 *
 * Usage: design OUT_DIR [MESH.obj]
 * Reads the mesh from MESH.obj or generates a parabolic vault, lets the library's start search
 * choose the initial field (printing every candidate it probed), steps the field optimisation
 * until it converges while printing progress, extracts level curves and builds rectifying strips
 * on them, prints the verdict (whether the strips meet theta), and writes OUT_DIR/mesh.obj,
 * OUT_DIR/field.csv (x,y,z,field per vertex), OUT_DIR/binormals.csv (x,y,z,bx,by,bz per vertex;
 * zero at boundary vertices), OUT_DIR/curves.obj (the level polylines as `l` lines) and
 * OUT_DIR/strips.obj (the strips' planar quads, one group each). Strips that miss theta
 * (LML_STATUS_NO_ACCEPTABLE_FAMILY) are written all the same: the exit status is non-zero only
 * when a call fails. */
#include "lamella.h"
#include "vault.h"

#include <stdio.h>
#include <stdlib.h>

#define THETA 60.0
#define STEP 5
#define MAX_ITERATIONS 300
/* Strip layout: this many level curves, resampled at this spacing, strips this wide. */
#define CURVES 6
#define SPACING 0.5
#define WIDTH 0.4

/* Prints the failure and returns 0 when `status` is an error. */
static int ok(LmlStatus status, const char *what)
{
    if (status >= 0) {
        return 1;
    }
    fprintf(stderr, "%s failed: %s: %s\n", what, lml_status_name(status), lml_last_error_message());
    return 0;
}

/* The per-vertex doubles of `get` (two-call pattern), malloc'd, or NULL. */
static double *fetch(LmlStatus (*get)(const LmlField *, double *, size_t, size_t *), const LmlField *field,
                     const char *what)
{
    size_t needed = 0;
    double *out;
    LmlStatus status = get(field, NULL, 0, &needed);
    if (status != LML_STATUS_BUFFER_TOO_SMALL && !ok(status, what)) {
        return NULL;
    }
    out = malloc(needed * sizeof(double) + 1); /* + 1: never malloc(0) */
    if (out != NULL && !ok(get(field, out, needed, &needed), what)) {
        free(out);
        out = NULL;
    }
    return out;
}

static LmlMesh *load_mesh(const char *path)
{
    LmlMesh *mesh = NULL;
    Vault vault;
    if (path != NULL) {
        ok(lml_mesh_read_obj(path, &mesh), "lml_mesh_read_obj");
        return mesh;
    }
    if (!vault_generate(&vault, 24)) {
        fprintf(stderr, "out of memory\n");
        return NULL;
    }
    ok(lml_mesh_new(vault.xyz, vault.vertex_count, vault.triangles, vault.triangle_count, &mesh), "lml_mesh_new");
    vault_free(&vault);
    return mesh;
}

/* Prints candidate `i` of a search (its text through the two-call pattern), `*` marking the winner. */
static void print_candidate(const LmlSearch *search, size_t i, size_t winner)
{
    size_t needed = 0;
    char *text;
    if (lml_search_candidate_text(search, i, NULL, 0, &needed) != LML_STATUS_BUFFER_TOO_SMALL) {
        return;
    }
    text = malloc(needed);
    if (text != NULL && ok(lml_search_candidate_text(search, i, (uint8_t *)text, needed, &needed), "lml_search_candidate_text")) {
        printf("%c candidate %lu: %s\n", i == winner ? '*' : ' ', (unsigned long)i, text);
    }
    free(text);
}

/* The library's start search for `params` on `mesh`: steps it until every candidate is probed,
 * prints them, and returns the field that continues from the best one (or NULL). */
static LmlField *search_start(const LmlMesh *mesh, const LmlFieldParams *params)
{
    LmlSearch *search = NULL;
    LmlField *field = NULL;
    LmlStatus status = LML_STATUS_MORE;
    size_t count = 0, winner = 0, i;
    if (!ok(lml_search_new(mesh, params, &search), "lml_search_new")) {
        return NULL;
    }
    while (status == LML_STATUS_MORE) {
        status = lml_search_step(search);
    }
    if (ok(status, "lml_search_step") && ok(lml_search_candidate_count(search, &count), "lml_search_candidate_count") &&
        ok(lml_search_winner(search, &winner), "lml_search_winner")) {
        printf("start search: %lu candidates\n", (unsigned long)count);
        for (i = 0; i < count; i++) {
            print_candidate(search, i, winner);
        }
        ok(lml_search_field(search, &field), "lml_search_field");
    }
    lml_search_free(search);
    return field;
}

/* Writes the mesh as OBJ, the field and the binormals as CSV into `dir`. */
static int write_outputs(const char *dir, const LmlMesh *mesh, const double *xyz, size_t n, const double *field,
                         const double *binormals)
{
    char path[4096];
    FILE *file;
    size_t v, needed = 0;
    uint32_t *triangles;

    if (lml_mesh_triangles(mesh, NULL, 0, &needed) != LML_STATUS_BUFFER_TOO_SMALL) {
        return 0;
    }
    triangles = malloc(needed * sizeof(uint32_t));
    if (triangles == NULL || !ok(lml_mesh_triangles(mesh, triangles, needed, &needed), "lml_mesh_triangles")) {
        free(triangles);
        return 0;
    }
    snprintf(path, sizeof path, "%s/mesh.obj", dir);
    if ((file = fopen(path, "w")) == NULL) {
        free(triangles);
        return 0;
    }
    for (v = 0; v < n; v++) {
        fprintf(file, "v %.17g %.17g %.17g\n", xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
    }
    for (v = 0; v + 2 < needed; v += 3) {
        fprintf(file, "f %u %u %u\n", triangles[v] + 1, triangles[v + 1] + 1, triangles[v + 2] + 1);
    }
    free(triangles);
    fclose(file);

    snprintf(path, sizeof path, "%s/field.csv", dir);
    if ((file = fopen(path, "w")) == NULL) {
        return 0;
    }
    fprintf(file, "x,y,z,field\n");
    for (v = 0; v < n; v++) {
        fprintf(file, "%.17g,%.17g,%.17g,%.17g\n", xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2], field[v]);
    }
    fclose(file);

    snprintf(path, sizeof path, "%s/binormals.csv", dir);
    if ((file = fopen(path, "w")) == NULL) {
        return 0;
    }
    fprintf(file, "x,y,z,bx,by,bz\n");
    for (v = 0; v < n; v++) {
        fprintf(file, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2],
                binormals[3 * v], binormals[3 * v + 1], binormals[3 * v + 2]);
    }
    fclose(file);
    printf("wrote %s/mesh.obj, %s/field.csv, %s/binormals.csv\n", dir, dir, dir);
    return 1;
}

/* The two-call pattern for any array: `get(handle, out, capacity, needed)` through a wrapper,
 * malloc'd (`size` bytes per element), or NULL. */
typedef LmlStatus (*Getter)(const void *handle, void *out, size_t capacity, size_t *needed);

static void *fetch_any(Getter get, const void *handle, size_t size, size_t *count, const char *what)
{
    size_t needed = 0;
    void *out;
    LmlStatus status = get(handle, NULL, 0, &needed);
    if (status != LML_STATUS_BUFFER_TOO_SMALL && !ok(status, what)) {
        return NULL;
    }
    out = malloc(needed * size + 1); /* + 1: never malloc(0) */
    if (out != NULL && !ok(get(handle, out, needed, &needed), what)) {
        free(out);
        return NULL;
    }
    *count = needed;
    return out;
}

/* Typed adapters from the library's getters to `Getter`. */
static LmlStatus curve_offsets(const void *h, void *out, size_t capacity, size_t *needed)
{
    return lml_curves_offsets((const LmlCurves *)h, (size_t *)out, capacity, needed);
}
static LmlStatus curve_points(const void *h, void *out, size_t capacity, size_t *needed)
{
    return lml_curves_points((const LmlCurves *)h, (double *)out, capacity, needed);
}
static LmlStatus strip_offsets(const void *h, void *out, size_t capacity, size_t *needed)
{
    return lml_strips_quad_offsets((const LmlStrips *)h, (size_t *)out, capacity, needed);
}
static LmlStatus strip_vertices(const void *h, void *out, size_t capacity, size_t *needed)
{
    return lml_strips_vertices((const LmlStrips *)h, (double *)out, capacity, needed);
}
static LmlStatus strip_quads(const void *h, void *out, size_t capacity, size_t *needed)
{
    return lml_strips_quads((const LmlStrips *)h, (uint32_t *)out, capacity, needed);
}
static LmlStatus strip_metrics(const void *h, void *out, size_t capacity, size_t *needed)
{
    return lml_strips_metrics((const LmlStrips *)h, (LmlStripMetrics *)out, capacity, needed);
}

/* Writes `count` points as OBJ vertices. */
static void write_vertices(FILE *file, const double *xyz, size_t count)
{
    size_t v;
    for (v = 0; v < count; v++) {
        fprintf(file, "v %.17g %.17g %.17g\n", xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
    }
}

/* Writes the level polylines to DIR/curves.obj, one `l` line each. */
static int write_curves(const char *dir, const LmlCurves *curves)
{
    char path[4096];
    FILE *file;
    size_t c = 0, k = 0, i, p;
    size_t *offsets = fetch_any(curve_offsets, curves, sizeof(size_t), &c, "lml_curves_offsets");
    double *points = fetch_any(curve_points, curves, sizeof(double), &k, "lml_curves_points");
    int written = 0;
    snprintf(path, sizeof path, "%s/curves.obj", dir);
    if (offsets != NULL && points != NULL && (file = fopen(path, "w")) != NULL) {
        write_vertices(file, points, k / 3);
        for (i = 0; i + 1 < c; i++) {
            fprintf(file, "l");
            for (p = offsets[i]; p < offsets[i + 1]; p++) {
                fprintf(file, " %lu", (unsigned long)p + 1);
            }
            fprintf(file, "\n");
        }
        written = fclose(file) == 0;
    }
    free(offsets);
    free(points);
    return written;
}

/* Prints the strips' Table 4 measures and writes their quads to DIR/strips.obj, one group each. */
static int write_strips(const char *dir, const LmlStrips *strips)
{
    char path[4096];
    FILE *file;
    size_t s = 0, v = 0, q = 0, m = 0, i, j;
    size_t *offsets = fetch_any(strip_offsets, strips, sizeof(size_t), &s, "lml_strips_quad_offsets");
    double *xyz = fetch_any(strip_vertices, strips, sizeof(double), &v, "lml_strips_vertices");
    uint32_t *quads = fetch_any(strip_quads, strips, sizeof(uint32_t), &q, "lml_strips_quads");
    LmlStripMetrics *metrics = fetch_any(strip_metrics, strips, sizeof(LmlStripMetrics), &m, "lml_strips_metrics");
    LmlPatternMetrics pattern;
    int written = 0;
    snprintf(path, sizeof path, "%s/strips.obj", dir);
    if (offsets != NULL && xyz != NULL && quads != NULL && metrics != NULL &&
        ok(lml_strips_pattern_metrics(strips, &pattern), "lml_strips_pattern_metrics") &&
        (file = fopen(path, "w")) != NULL) {
        for (i = 0; i < m; i++) {
            printf("strip %lu: length %.2f  diff_theta %.3f deg  e_straight %.1e  max planarity %.1e%s\n",
                   (unsigned long)i, metrics[i].length, metrics[i].max_diff_theta_degrees, metrics[i].e_straight,
                   metrics[i].max_planar, metrics[i].warnings != 0 ? "  (warnings)" : "");
        }
        printf("%lu strips, %lu curves skipped; max diff_theta %.3f deg, max e_straight %.1e\n",
               (unsigned long)pattern.strip_count, (unsigned long)pattern.skipped_count,
               pattern.max_diff_theta_degrees, pattern.max_e_straight);
        write_vertices(file, xyz, v / 3);
        for (i = 0; i + 1 < s; i++) {
            fprintf(file, "g strip%lu\n", (unsigned long)i);
            for (j = offsets[i]; j < offsets[i + 1]; j++) {
                const uint32_t *quad = quads + 4 * j;
                fprintf(file, "f %u %u %u %u\n", quad[0] + 1, quad[1] + 1, quad[2] + 1, quad[3] + 1);
            }
        }
        written = fclose(file) == 0;
    }
    free(offsets);
    free(xyz);
    free(quads);
    free(metrics);
    return written;
}

/* Prints the verdict on the strips: the library's message when they miss theta (status
 * LML_STATUS_NO_ACCEPTABLE_FAMILY), else the worst quad within the tolerance. */
static int print_verdict(LmlStatus built, const LmlStrips *strips)
{
    LmlVerdict verdict;
    if (built == LML_STATUS_NO_ACCEPTABLE_FAMILY) {
        /* Read before any other call: the message belongs to the last call. */
        printf("verdict: %s\n", lml_last_error_message());
    }
    if (!ok(lml_strips_verdict(strips, &verdict), "lml_strips_verdict")) {
        return 0;
    }
    if (verdict.acceptable) {
        printf("verdict: acceptable, every strip within %.1f deg of theta (worst: strip %lu quad %lu, %.3f deg off)\n",
               verdict.tolerance_degrees, (unsigned long)verdict.worst_strip, (unsigned long)verdict.worst_quad,
               verdict.worst_error_degrees);
    }
    return 1;
}

/* Level curves of the converged field, strips on them, both written as OBJ. */
static int design_strips(const char *dir, const LmlField *field)
{
    LmlCurves *curves = NULL;
    LmlStrips *strips = NULL;
    LmlStripParams params;
    LmlStatus built = LML_STATUS_INVALID_ARGUMENT;
    int success = ok(lml_curves_new_uniform(field, CURVES, SPACING, &curves), "lml_curves_new_uniform") &&
                  ok(lml_strip_params_default(THETA, WIDTH, &params), "lml_strip_params_default") &&
                  ok(built = lml_strips_new(curves, &params, &strips), "lml_strips_new") && print_verdict(built, strips) &&
                  write_curves(dir, curves) && write_strips(dir, strips);
    if (success) {
        printf("wrote %s/curves.obj, %s/strips.obj\n", dir, dir);
    }
    lml_strips_free(strips);
    lml_curves_free(curves);
    return success;
}

int main(int argc, char **argv)
{
    LmlMesh *mesh;
    LmlField *field = NULL;
    LmlFieldParams params;
    LmlReport report;
    LmlStatus status = LML_STATUS_MORE;
    double *xyz = NULL, *values = NULL, *binormals = NULL;
    size_t n = 0;
    int success = 0;

    if (argc < 2) {
        fprintf(stderr, "usage: %s OUT_DIR [MESH.obj]\n", argv[0]);
        return 2;
    }
    printf("lamella %s (ABI %u)\n", lml_version(), lml_abi_version());
    mesh = load_mesh(argc > 2 ? argv[2] : NULL);
    if (mesh == NULL || !ok(lml_mesh_vertex_count(mesh, &n), "lml_mesh_vertex_count")) {
        lml_mesh_free(mesh);
        return 1;
    }
    printf("%lu vertices, theta = %.0f degrees\n", (unsigned long)n, THETA);
    xyz = malloc(3 * n * sizeof(double));
    if (xyz != NULL && ok(lml_mesh_positions(mesh, xyz, 3 * n, &n), "lml_mesh_positions") &&
        ok(lml_field_params_default(LML_FAMILY_PSEUDO_GEODESIC, THETA, &params), "params") &&
        (field = search_start(mesh, &params)) != NULL) {
        n /= 3;
        do {
            status = lml_field_step(field, STEP, &report);
            if (!ok(status, "lml_field_step")) {
                break;
            }
            printf("iteration %3lu: E_angle %.3e  max angle error %7.3f deg  singular vertices %lu\n",
                   (unsigned long)report.iterations, report.energy_angle, report.angle_error_max_degrees,
                   (unsigned long)report.singular_vertex_count);
        } while (status == LML_STATUS_MORE && report.iterations < MAX_ITERATIONS);
        printf("%s after %lu iterations\n", status == LML_STATUS_CONVERGED ? "converged" : "stopped",
               (unsigned long)report.iterations);
        values = fetch(lml_field_values, field, "lml_field_values");
        binormals = fetch(lml_field_binormals, field, "lml_field_binormals");
        success = status == LML_STATUS_CONVERGED && values != NULL && binormals != NULL &&
                  write_outputs(argv[1], mesh, xyz, n, values, binormals) && design_strips(argv[1], field);
    }
    free(values);
    free(binormals);
    free(xyz);
    lml_field_free(field);
    lml_mesh_free(mesh);
    return success ? 0 : 1;
}
