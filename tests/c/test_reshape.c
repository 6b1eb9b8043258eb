/* Surface optimisation through the C ABI (paper Sec. 3.3): the cylinder moved so that the level
 * sets of its initial field approach a 45 degree family, within an absolute tolerance; every
 * invalid input, stepping to convergence, positions and deviations with the two-call pattern,
 * the deviations checked against the distance from the cylinder's axis; a saved session restored
 * and stepped on in step with the original, and damaged bytes refused. */
#include "check.h"
#include "harness.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define RESHAPE_BUDGET 300
#define RESHAPE_TOLERANCE 0.2

/* The positions of `reshape` (3 n values), or NULL when they cannot be read. */
static double *positions_of(const LmlReshape *reshape, size_t n)
{
    size_t needed = 0;
    double *xyz = malloc(3 * n * sizeof(double));
    if (xyz != NULL && lml_reshape_positions(reshape, xyz, 3 * n, &needed) != LML_STATUS_OK) {
        free(xyz);
        xyz = NULL;
    }
    return xyz;
}

/* Saves `reshape`, restores it, and steps both three iterations: the same bits before and after.
 * Damaged bytes, a field session's bytes and NULL arguments are refused. */
static void save_and_restore(LmlReshape *reshape, size_t n)
{
    size_t size = 0, needed = 0;
    unsigned char *bytes;
    LmlReshape *restored = NULL;
    LmlReshapeReport a, b;
    double *before, *after;

    CHECK_STATUS(lml_reshape_save(reshape, NULL, 0, &size), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(size > 8);
    CHECK_STATUS(lml_reshape_save(NULL, NULL, 0, &size), LML_STATUS_INVALID_ARGUMENT);
    bytes = malloc(size);
    if (bytes == NULL) {
        CHECK(!"out of memory");
        return;
    }
    CHECK_STATUS(lml_reshape_save(reshape, bytes, size - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_reshape_save(reshape, bytes, size, &needed), LML_STATUS_OK);
    CHECK(needed == size && memcmp(bytes, "LMLR", 4) == 0);

    CHECK_STATUS(lml_reshape_load(bytes, size, &restored), LML_STATUS_OK);
    CHECK(restored != NULL);
    if (restored != NULL) {
        LmlStatus original = lml_reshape_step(reshape, 3, &a);
        CHECK_STATUS(lml_reshape_step(restored, 3, &b), original);
        CHECK(a.iterations == b.iterations && a.max_deviation == b.max_deviation && a.energy_angle == b.energy_angle);
        before = positions_of(reshape, n);
        after = positions_of(restored, n);
        CHECK(before != NULL && after != NULL && memcmp(before, after, 3 * n * sizeof(double)) == 0);
        free(before);
        free(after);
        lml_reshape_free(restored);
    }

    restored = NULL;
    CHECK_STATUS(lml_reshape_load(bytes, size / 2, &restored), LML_STATUS_CORRUPT_DATA);
    CHECK(restored == NULL);
    CHECK_STATUS(lml_reshape_load(bytes, 0, &restored), LML_STATUS_CORRUPT_DATA);
    bytes[3] = 'F'; /* "LMLF": a field session's magic */
    CHECK_STATUS(lml_reshape_load(bytes, size, &restored), LML_STATUS_CORRUPT_DATA);
    CHECK_MESSAGE("surface session");
    CHECK(restored == NULL);
    CHECK_STATUS(lml_reshape_load(NULL, 5, &restored), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_reshape_load(bytes, size, NULL), LML_STATUS_INVALID_ARGUMENT);
    free(bytes);
}

void test_reshape(const Cylinder *c)
{
    LmlMesh *mesh = NULL;
    LmlReshape *reshape = NULL;
    LmlReshapeReport report;
    LmlStatus status = LML_STATUS_MORE;
    size_t n = c->vertex_count, v, needed = 0;
    unsigned steps = 0;
    double *xyz = malloc(3 * n * sizeof(double));
    double *deviations = malloc(n * sizeof(double));
    double *constant = malloc(n * sizeof(double));
    double largest = 0.0, sagitta;
    if (xyz == NULL || deviations == NULL || constant == NULL) {
        CHECK(!"out of memory");
        free(xyz);
        free(deviations);
        free(constant);
        return;
    }
    for (v = 0; v < n; v++) {
        constant[v] = 1.0;
    }
    CHECK_STATUS(lml_mesh_new(c->xyz, c->vertex_count, c->triangles, c->triangle_count, &mesh), LML_STATUS_OK);

    /* Invalid inputs, each refused with the session left NULL. */
    CHECK_STATUS(lml_reshape_new(NULL, c->field, n, 45.0, RESHAPE_TOLERANCE, 0, &reshape), LML_STATUS_INVALID_ARGUMENT);
    CHECK(reshape == NULL);
    CHECK_STATUS(lml_reshape_new(mesh, c->field, n - 1, 45.0, RESHAPE_TOLERANCE, 0, &reshape), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_reshape_new(mesh, NULL, n, 45.0, RESHAPE_TOLERANCE, 0, &reshape), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_reshape_new(mesh, c->field, n, 200.0, RESHAPE_TOLERANCE, 0, &reshape), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("theta");
    CHECK_STATUS(lml_reshape_new(mesh, c->field, n, 45.0, -1.0, 0, &reshape), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("tolerance");
    CHECK_STATUS(lml_reshape_new(mesh, c->field, n, 45.0, NAN, 1, &reshape), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("tolerance");
    CHECK_STATUS(lml_reshape_new(mesh, constant, n, 45.0, RESHAPE_TOLERANCE, 0, &reshape), LML_STATUS_SINGULAR_FIELD);
    CHECK(reshape == NULL);
    CHECK_STATUS(lml_reshape_new(mesh, c->field, n, 45.0, RESHAPE_TOLERANCE, 0, NULL), LML_STATUS_INVALID_ARGUMENT);

    CHECK_STATUS(lml_reshape_new(mesh, c->field, n, 45.0, RESHAPE_TOLERANCE, 0, &reshape), LML_STATUS_OK);
    CHECK(reshape != NULL);
    lml_mesh_free(mesh);
    if (reshape == NULL) {
        free(xyz);
        free(deviations);
        free(constant);
        return;
    }
    CHECK_STATUS(lml_reshape_report(reshape, &report), LML_STATUS_OK);
    CHECK(report.iterations == 0 && report.max_deviation == 0.0);
    CHECK(fabs(report.tolerance - RESHAPE_TOLERANCE) < 1e-12);
    CHECK_STATUS(lml_reshape_report(reshape, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_reshape_step(NULL, 1, &report), LML_STATUS_INVALID_ARGUMENT);
    while (status == LML_STATUS_MORE && steps < RESHAPE_BUDGET / 10) {
        status = lml_reshape_step(reshape, 10, &report);
        steps++;
    }
    CHECK(status == LML_STATUS_MORE || status == LML_STATUS_CONVERGED);
    CHECK(report.iterations > 0);
    CHECK(report.max_deviation > 0.0 && report.max_deviation <= RESHAPE_TOLERANCE);
    CHECK(report.rms_deviation <= report.max_deviation);
    CHECK(isfinite(report.energy_angle) && isfinite(report.energy_fair) && isfinite(report.energy_close) && isfinite(report.energy_edge));
    save_and_restore(reshape, n);
    CHECK_STATUS(lml_reshape_report(reshape, &report), LML_STATUS_OK);

    /* Two-call arrays: the size first, then the values. */
    CHECK_STATUS(lml_reshape_positions(reshape, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == 3 * n);
    CHECK_STATUS(lml_reshape_positions(reshape, xyz, 3 * n - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_reshape_positions(reshape, xyz, 3 * n, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_reshape_positions(reshape, xyz, 3 * n, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_reshape_deviations(reshape, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == n);
    CHECK_STATUS(lml_reshape_deviations(reshape, deviations, n, &needed), LML_STATUS_OK);
    /* The original surface lies between the cylinder and its chords: a vertex's distance from it
     * is at least its distance from the cylinder less the sagitta of the widest cell, and, away
     * from the patch's edges (past which a vertex may slide), at most that plus the sagitta. */
    sagitta = CYLINDER_RADIUS * (1.0 - cos(0.5 * 1.5 * CYLINDER_SPAN_DEGREES / (double)c->columns * 3.14159265358979323846 / 180.0));
    for (v = 0; v < n; v++) {
        const double *p = xyz + 3 * v;
        double radial = fabs(sqrt(p[0] * p[0] + p[1] * p[1]) - CYLINDER_RADIUS);
        double phi = atan2(p[1], p[0]) * 180.0 / 3.14159265358979323846;
        int inside = p[2] > 1.0 && p[2] < CYLINDER_HEIGHT - 1.0 && phi > 5.0 && phi < CYLINDER_SPAN_DEGREES - 5.0;
        CHECK(deviations[v] >= 0.0 && deviations[v] <= RESHAPE_TOLERANCE);
        CHECK(deviations[v] >= radial - sagitta - 1e-9);
        CHECK(!inside || deviations[v] <= radial + sagitta + 1e-9);
        largest = fmax(largest, deviations[v]);
    }
    CHECK(largest == report.max_deviation);
    lml_reshape_free(reshape);
    lml_reshape_free(NULL);
    free(xyz);
    free(deviations);
    free(constant);
}
