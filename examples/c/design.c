/* Designs a theta = 60 degree pseudo-geodesic field through Lamella's C ABI, step by step.
 *
 * Usage: design OUT_DIR [MESH.obj]
 * Reads the mesh from MESH.obj or generates a parabolic vault, starts from the coordinate along
 * the mesh's longest extent, steps the optimisation until it converges while printing progress,
 * and writes OUT_DIR/mesh.obj, OUT_DIR/field.csv (x,y,z,field per vertex) and
 * OUT_DIR/binormals.csv (x,y,z,bx,by,bz per vertex; zero at boundary vertices). */
#include "lamella.h"
#include "vault.h"

#include <stdio.h>
#include <stdlib.h>

#define THETA 60.0
#define STEP 5
#define MAX_ITERATIONS 300

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

/* The coordinate along the longest side of the bounding box, per vertex. */
static double *initial_field(const double *xyz, size_t n)
{
    double lo[3], hi[3];
    double *field = malloc(n * sizeof(double) + 1); /* + 1: never malloc(0) */
    size_t v;
    int k, axis = 0;
    if (field == NULL) {
        return NULL;
    }
    for (k = 0; k < 3; k++) {
        lo[k] = hi[k] = xyz[k];
    }
    for (v = 0; v < n; v++) {
        for (k = 0; k < 3; k++) {
            lo[k] = xyz[3 * v + k] < lo[k] ? xyz[3 * v + k] : lo[k];
            hi[k] = xyz[3 * v + k] > hi[k] ? xyz[3 * v + k] : hi[k];
        }
    }
    for (k = 1; k < 3; k++) {
        axis = hi[k] - lo[k] > hi[axis] - lo[axis] ? k : axis;
    }
    for (v = 0; v < n; v++) {
        field[v] = xyz[3 * v + axis];
    }
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

int main(int argc, char **argv)
{
    LmlMesh *mesh;
    LmlField *field = NULL;
    LmlFieldParams params;
    LmlReport report;
    LmlStatus status = LML_STATUS_MORE;
    double *xyz = NULL, *start = NULL, *values = NULL, *binormals = NULL;
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
    xyz = malloc(3 * n * sizeof(double));
    if (xyz != NULL && ok(lml_mesh_positions(mesh, xyz, 3 * n, &n), "lml_mesh_positions")) {
        n /= 3;
        start = initial_field(xyz, n);
    }
    if (start != NULL && ok(lml_field_params_default(LML_FAMILY_PSEUDO_GEODESIC, THETA, &params), "params") &&
        ok(lml_field_new(mesh, start, n, &params, &field), "lml_field_new")) {
        printf("%lu vertices, theta = %.0f degrees\n", (unsigned long)n, THETA);
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
                  write_outputs(argv[1], mesh, xyz, n, values, binormals);
    }
    free(values);
    free(binormals);
    free(start);
    free(xyz);
    lml_field_free(field);
    lml_mesh_free(mesh);
    return success ? 0 : 1;
}
