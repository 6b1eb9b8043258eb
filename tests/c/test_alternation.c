/* The alternating schedule through the C ABI (paper Sec. 3.3): field steps and surface steps in
 * turn on the cylinder towards a 45 degree family, within an absolute tolerance; every invalid
 * input, stepping a round and then more, positions, field and deviations with the two-call
 * pattern, and the level curves of the resulting field on the moved surface measured here
 * against that surface's normals. */
#include "check.h"
#include "harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define ALTERNATION_TOLERANCE 0.2
#define ALTERNATION_ITERATIONS 50
#define ALTERNATION_THETA 45.0

/* `count` doubles read with the two-call pattern from `get`, or NULL. */
static double *read_doubles(LmlStatus (*get)(const LmlAlternation *, double *, size_t, size_t *), const LmlAlternation *a, size_t count)
{
    size_t needed = 0;
    double *values = malloc(count * sizeof(double));
    CHECK_STATUS(get(a, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == count);
    CHECK_STATUS(get(a, values, count, NULL), LML_STATUS_INVALID_ARGUMENT);
    if (values != NULL && get(a, values, count, &needed) != LML_STATUS_OK) {
        CHECK(!"values read");
        free(values);
        values = NULL;
    }
    return values;
}

/* `count` doubles of a curves handle, or NULL. */
static double *curve_values(LmlStatus (*get)(const LmlCurves *, double *, size_t, size_t *), const LmlCurves *curves, size_t count)
{
    size_t needed = 0;
    double *values = malloc((count > 0 ? count : 1) * sizeof(double));
    if (values != NULL && get(curves, values, count, &needed) != LML_STATUS_OK) {
        free(values);
        values = NULL;
    }
    return values;
}

/* The level curves of `field` on the surface (`xyz`, the cylinder's triangles), resampled every
 * `spacing`: the binormal of every inner point against the surface normal there, against θ. */
static void measure_curves(const Cylinder *c, const double *xyz, const double *field)
{
    LmlMesh *moved = NULL;
    LmlField *session = NULL;
    LmlCurves *curves = NULL;
    LmlFieldParams params;
    size_t count = 0, needed = 0, i, p, measured = 0;
    size_t *offsets = NULL;
    double *points = NULL, *normals = NULL, worst = 0.0, sum = 0.0;
    CHECK_STATUS(lml_mesh_new(xyz, c->vertex_count, c->triangles, c->triangle_count, &moved), LML_STATUS_OK);
    CHECK_STATUS(lml_field_params_default(LML_FAMILY_PSEUDO_GEODESIC, ALTERNATION_THETA, &params), LML_STATUS_OK);
    CHECK_STATUS(lml_field_new(moved, field, c->vertex_count, &params, &session), LML_STATUS_OK);
    /* Every three cells along the curves (the cells are about 1.6 long). */
    CHECK_STATUS(lml_curves_new_uniform(session, 5, 4.8, &curves), LML_STATUS_OK);
    if (curves != NULL && lml_curves_count(curves, &count) == LML_STATUS_OK) {
        offsets = malloc((count + 1) * sizeof(size_t));
        if (offsets != NULL && lml_curves_offsets(curves, offsets, count + 1, &needed) == LML_STATUS_OK) {
            points = curve_values(lml_curves_points, curves, 3 * offsets[count]);
            normals = curve_values(lml_curves_normals, curves, 3 * offsets[count]);
        }
    }
    CHECK(points != NULL && normals != NULL && count >= 5);
    if (points != NULL && normals != NULL) {
        for (i = 0; i < count; i++) {
            for (p = offsets[i] + 1; p + 1 < offsets[i + 1]; p++) {
                double error = fabs(binormal_angle(points + 3 * (p - 1), points + 3 * p, points + 3 * (p + 1), normals + 3 * p) - ALTERNATION_THETA);
                worst = fmax(worst, error);
                sum += error;
                measured++;
            }
        }
        printf("  alternation: %lu curves, binormal angle error against the moved surface's normals mean %.2f max %.2f deg over %lu points\n",
               (unsigned long)count, measured ? sum / (double)measured : 0.0, worst, (unsigned long)measured);
        CHECK(measured >= 10);
        CHECK(measured > 0 && sum / (double)measured < 1.0);
        CHECK(worst < 3.0);
    }
    free(offsets);
    free(points);
    free(normals);
    lml_curves_free(curves);
    lml_field_free(session);
    lml_mesh_free(moved);
}

void test_alternation(const Cylinder *c)
{
    LmlMesh *mesh = NULL;
    LmlAlternation *alternation = NULL;
    LmlAlternationReport report, first;
    LmlStatus status;
    size_t n = c->vertex_count, v;
    double *xyz, *field, *deviations, largest = 0.0, moved = 0.0;
    int changed = 0;

    CHECK_STATUS(lml_mesh_new(c->xyz, c->vertex_count, c->triangles, c->triangle_count, &mesh), LML_STATUS_OK);
    /* Invalid inputs, each refused with the session left NULL. */
    CHECK_STATUS(lml_alternation_new(NULL, c->field, n, ALTERNATION_THETA, ALTERNATION_TOLERANCE, 0, ALTERNATION_ITERATIONS, &alternation), LML_STATUS_INVALID_ARGUMENT);
    CHECK(alternation == NULL);
    CHECK_STATUS(lml_alternation_new(mesh, c->field, n - 1, ALTERNATION_THETA, ALTERNATION_TOLERANCE, 0, ALTERNATION_ITERATIONS, &alternation), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_alternation_new(mesh, NULL, n, ALTERNATION_THETA, ALTERNATION_TOLERANCE, 0, ALTERNATION_ITERATIONS, &alternation), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_alternation_new(mesh, c->field, n, 200.0, ALTERNATION_TOLERANCE, 0, ALTERNATION_ITERATIONS, &alternation), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("theta");
    CHECK_STATUS(lml_alternation_new(mesh, c->field, n, ALTERNATION_THETA, 0.0, 0, ALTERNATION_ITERATIONS, &alternation), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("tolerance");
    CHECK_STATUS(lml_alternation_new(mesh, c->field, n, ALTERNATION_THETA, ALTERNATION_TOLERANCE, 0, 0, &alternation), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("iterations_per_step");
    CHECK_STATUS(lml_alternation_new(mesh, c->field, n, ALTERNATION_THETA, ALTERNATION_TOLERANCE, 0, ALTERNATION_ITERATIONS, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK(alternation == NULL);

    CHECK_STATUS(lml_alternation_new(mesh, c->field, n, ALTERNATION_THETA, ALTERNATION_TOLERANCE, 0, ALTERNATION_ITERATIONS, &alternation), LML_STATUS_OK);
    lml_mesh_free(mesh);
    if (alternation == NULL) {
        return;
    }
    CHECK_STATUS(lml_alternation_report(alternation, &report), LML_STATUS_OK);
    CHECK(report.rounds == 0 && report.converged == 0 && report.surface.max_deviation == 0.0);
    CHECK(fabs(report.surface.tolerance - ALTERNATION_TOLERANCE) < 1e-12);
    CHECK_STATUS(lml_alternation_report(alternation, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_alternation_step(NULL, 1, &report), LML_STATUS_INVALID_ARGUMENT);

    /* One round, then up to three more. */
    status = lml_alternation_step(alternation, 1, &first);
    CHECK(status == LML_STATUS_MORE || status == LML_STATUS_CONVERGED);
    CHECK(first.rounds == 1 && first.rounds_this_step == 1);
    CHECK(first.field.iterations > 0 && first.surface.iterations > 0);
    status = lml_alternation_step(alternation, 9, &report);
    CHECK(status == LML_STATUS_MORE || status == LML_STATUS_CONVERGED);
    CHECK(report.rounds == first.rounds + report.rounds_this_step && report.rounds_this_step <= 9);
    CHECK(report.surface.max_deviation > 0.0 && report.surface.max_deviation <= ALTERNATION_TOLERANCE);
    CHECK(isfinite(report.field.energy_angle) && isfinite(report.surface.energy_angle));
    printf("  alternation: %lu rounds (%s), last field step %lu iterations, surface deviation %.4f (tolerance %.2f)\n", (unsigned long)report.rounds,
           status == LML_STATUS_CONVERGED ? "converged" : "not converged", (unsigned long)report.field.iterations, report.surface.max_deviation, ALTERNATION_TOLERANCE);

    xyz = read_doubles(lml_alternation_positions, alternation, 3 * n);
    field = read_doubles(lml_alternation_field, alternation, n);
    deviations = read_doubles(lml_alternation_deviations, alternation, n);
    if (xyz != NULL && field != NULL && deviations != NULL) {
        for (v = 0; v < n; v++) {
            const double *p = xyz + 3 * v, *o = c->xyz + 3 * v;
            CHECK(deviations[v] >= 0.0 && deviations[v] <= ALTERNATION_TOLERANCE);
            CHECK(isfinite(field[v]));
            largest = fmax(largest, deviations[v]);
            moved = fmax(moved, sqrt((p[0] - o[0]) * (p[0] - o[0]) + (p[1] - o[1]) * (p[1] - o[1]) + (p[2] - o[2]) * (p[2] - o[2])));
            changed = changed || field[v] != c->field[v];
        }
        CHECK(largest == report.surface.max_deviation);
        CHECK(moved > 0.0 && changed);
        measure_curves(c, xyz, field);
    }
    free(xyz);
    free(field);
    free(deviations);
    lml_alternation_free(alternation);
    lml_alternation_free(NULL);
}
