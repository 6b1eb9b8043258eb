/* Constant-slope families (paper Sec. 5.2.3, Eq. 22) on the cylinder: about its own axis every
 * tangent plane is reachable and the curves of slope beta are helices, straight lines rising at
 * beta in the development; about an axis across it, the reachable region ends on the ruling where
 * the tangent planes themselves have the slope. */
#include "check.h"
#include "harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define PI 3.14159265358979323846
#define SLOPE 30.0
#define STEP 10
#define BUDGET 200
/* ISOPHOTE_MARGIN_DEGREES of the library: the reachable region starts this far inside. */
#define MARGIN 3.0

/* Every invalid input of the slope functions, each refused naming the element. */
static void invalid_inputs(const LmlMesh *mesh, size_t n)
{
    const double z[3] = {0.0, 0.0, 1.0}, zero[3] = {0.0, 0.0, 0.0}, nan_axis[3] = {NAN, 0.0, 1.0};
    LmlFieldParams params;
    LmlCurves *curves = (LmlCurves *)&params;
    LmlSearch *search = NULL;
    size_t needed = 0;
    double *values = malloc(n * sizeof(double));

    CHECK_STATUS(lml_field_params_default(LML_FAMILY_CONSTANT_SLOPE, 90.0, &params), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("(−90, 90)");
    CHECK_STATUS(lml_field_params_default(LML_FAMILY_FREE_SLOPE, NAN, &params), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_field_values_from_slope(NULL, z, SLOPE, values, n, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_field_values_from_slope(mesh, NULL, SLOPE, values, n, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("axis");
    CHECK_STATUS(lml_field_values_from_slope(mesh, zero, SLOPE, values, n, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("axis");
    CHECK_STATUS(lml_field_values_from_slope(mesh, nan_axis, SLOPE, values, n, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_field_values_from_slope(mesh, z, -95.0, values, n, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("slope");
    CHECK_STATUS(lml_curves_new_reachable_boundary(mesh, zero, SLOPE, &curves), LML_STATUS_INVALID_ARGUMENT);
    CHECK(curves == NULL);
    CHECK_STATUS(lml_curves_new_reachable_boundary(mesh, z, INFINITY, &curves), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("slope_degrees");
    CHECK_STATUS(lml_curves_new_reachable_boundary(NULL, z, SLOPE, &curves), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_curves_new_reachable_boundary(mesh, z, SLOPE, NULL), LML_STATUS_INVALID_ARGUMENT);
    /* The start search covers the families by angle; it refuses a slope family by name. */
    CHECK_STATUS(lml_field_params_default(LML_FAMILY_CONSTANT_SLOPE, SLOPE, &params), LML_STATUS_OK);
    CHECK_STATUS(lml_search_new(mesh, &params, &search), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("family");
    CHECK(search == NULL);
    free(values);
}

/* Reads all points of `curves` (malloc'd, 3 doubles each) and the polyline offsets. */
static double *curve_points(const LmlCurves *curves, size_t **offsets, size_t *count)
{
    size_t needed = 0, points_needed = 0;
    double *points;
    LmlStatus status;
    CHECK_STATUS(lml_curves_count(curves, count), LML_STATUS_OK);
    CHECK_STATUS(lml_curves_offsets(curves, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    status = lml_curves_points(curves, NULL, 0, &points_needed);
    CHECK(status == (points_needed == 0 ? LML_STATUS_OK : LML_STATUS_BUFFER_TOO_SMALL));
    *offsets = malloc(needed * sizeof(size_t));
    points = malloc((points_needed + 1) * sizeof(double));
    if (*offsets == NULL || points == NULL) {
        free(*offsets);
        free(points);
        *offsets = NULL;
        return NULL;
    }
    CHECK_STATUS(lml_curves_offsets(curves, *offsets, needed, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_curves_points(curves, points, points_needed, &points_needed), LML_STATUS_OK);
    return points;
}

/* A free slope started at 20 degrees on the field of the 30 degree helices is fitted to them before
 * the first iteration; a session of another family has no slope. */
static void free_slope(const LmlMesh *mesh, const Cylinder *c, const double *helices)
{
    LmlFieldParams params;
    LmlField *field = NULL, *other = NULL;
    LmlReport report;
    double reached = 0.0;
    CHECK_STATUS(lml_field_params_default(LML_FAMILY_FREE_SLOPE, 20.0, &params), LML_STATUS_OK);
    CHECK_STATUS(lml_field_new(mesh, helices, c->vertex_count, &params, &field), LML_STATUS_OK);
    CHECK_STATUS(lml_field_step(field, 1, &report), LML_STATUS_MORE);
    CHECK_STATUS(lml_field_slope(field, &reached), LML_STATUS_OK);
    CHECK(fabs(reached - SLOPE) < 1.0);
    printf("  free slope started at 20 deg on the %.0f deg helices: fitted %.3f deg\n", SLOPE, reached);
    CHECK_STATUS(lml_field_params_default(LML_FAMILY_PSEUDO_GEODESIC, 60.0, &params), LML_STATUS_OK);
    CHECK_STATUS(lml_field_new(mesh, helices, c->vertex_count, &params, &other), LML_STATUS_OK);
    CHECK_STATUS(lml_field_slope(other, &reached), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("constant-slope");
    CHECK_STATUS(lml_field_slope(NULL, &reached), LML_STATUS_INVALID_ARGUMENT);
    lml_field_free(field);
    lml_field_free(other);
}

/* Slope about the cylinder's axis: every level curve rises at SLOPE, measured by the chord over
 * two resampled points against the z axis (t.z = sin beta). */
static void helices(const LmlMesh *mesh, const Cylinder *c)
{
    const double z[3] = {0.0, 0.0, 1.0};
    LmlFieldParams params;
    LmlField *field = NULL;
    LmlCurves *curves = NULL;
    LmlReport report;
    LmlStatus status = LML_STATUS_MORE;
    size_t needed = 0, count = 0, *offsets = NULL, i, k, measured = 0;
    double *start = malloc(c->vertex_count * sizeof(double)), *points, worst = 0.0, reached = 0.0;

    if (start == NULL) {
        CHECK(!"out of memory");
        return;
    }
    CHECK_STATUS(lml_field_values_from_slope(mesh, z, SLOPE, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == c->vertex_count);
    CHECK_STATUS(lml_field_values_from_slope(mesh, z, SLOPE, start, c->vertex_count, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_field_params_default(LML_FAMILY_CONSTANT_SLOPE, SLOPE, &params), LML_STATUS_OK);
    CHECK(params.slope_axis[0] == 0.0 && params.slope_axis[1] == 0.0 && params.slope_axis[2] == 1.0);
    CHECK(params.theta_degrees == SLOPE);
    CHECK_STATUS(lml_field_new(mesh, start, c->vertex_count, &params, &field), LML_STATUS_OK);
    while (field != NULL && status == LML_STATUS_MORE && report.iterations < BUDGET) {
        status = lml_field_step(field, STEP, &report);
    }
    CHECK(status == LML_STATUS_CONVERGED);
    CHECK_STATUS(lml_curves_new_uniform(field, 6, 1.0, &curves), LML_STATUS_OK);
    points = curve_points(curves, &offsets, &count);
    CHECK(count >= 4);
    for (k = 0; points != NULL && k < count; k++) {
        for (i = offsets[k] + 1; i + 1 < offsets[k + 1]; i++) {
            const double *a = points + 3 * (i - 1), *b = points + 3 * (i + 1);
            double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
            double length = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            double slope = asin(fabs(d[2]) / length) * 180.0 / PI;
            worst = fmax(worst, fabs(slope - SLOPE));
            measured++;
        }
    }
    CHECK(measured > 50);
    CHECK(worst < 1.0);
    CHECK_STATUS(lml_field_slope(field, &reached), LML_STATUS_OK);
    CHECK(reached == SLOPE);
    CHECK_STATUS(lml_field_slope(field, NULL), LML_STATUS_INVALID_ARGUMENT);
    free_slope(mesh, c, start);
    printf("  constant slope %.0f deg about the cylinder's axis: %zu curves, %zu points, worst slope error %.3f deg after %llu iterations\n",
           SLOPE, count, measured, worst, (unsigned long long)report.iterations);
    free(offsets);
    free(points);
    free(start);
    lml_curves_free(curves);
    lml_field_free(field);
}

/* About the x axis the tangent plane at the angle phi around the cylinder has the inclination
 * min(phi, 180 - phi), so the slope SLOPE is reachable between the rulings at phi = SLOPE + MARGIN
 * and 180 - (SLOPE + MARGIN), both inside the 150 degree patch: two vertical lines. */
static void reachable_boundary(const LmlMesh *mesh)
{
    const double x[3] = {2.0, 0.0, 0.0}, z[3] = {0.0, 0.0, 1.0};
    const double rulings[2] = {SLOPE + MARGIN, 180.0 - (SLOPE + MARGIN)};
    LmlCurves *curves = NULL;
    size_t count = 0, *offsets = NULL, i, k, found[2] = {0, 0};
    double *points, worst = 0.0;

    CHECK_STATUS(lml_curves_new_reachable_boundary(mesh, z, SLOPE, &curves), LML_STATUS_OK);
    CHECK_STATUS(lml_curves_count(curves, &count), LML_STATUS_OK);
    CHECK(count == 0); /* every tangent plane contains the axis: all reachable */
    lml_curves_free(curves);

    CHECK_STATUS(lml_curves_new_reachable_boundary(mesh, x, SLOPE, &curves), LML_STATUS_OK);
    points = curve_points(curves, &offsets, &count);
    CHECK(count == 2);
    for (k = 0; points != NULL && k < count; k++) {
        const double *first = points + 3 * offsets[k];
        double low = INFINITY, high = -INFINITY;
        /* The ruling this polyline follows: the nearer of the two. */
        size_t r = fabs(atan2(first[1], first[0]) * 180.0 / PI - rulings[0]) < 45.0 ? 0 : 1;
        found[r]++;
        for (i = offsets[k]; i < offsets[k + 1]; i++) {
            const double *p = points + 3 * i;
            worst = fmax(worst, fabs(atan2(p[1], p[0]) * 180.0 / PI - rulings[r]));
            low = fmin(low, p[2]);
            high = fmax(high, p[2]);
        }
        CHECK(high - low > 0.99 * CYLINDER_HEIGHT);
    }
    CHECK(found[0] == 1 && found[1] == 1);
    CHECK(worst < 1.0);
    printf("  reachable boundary of slope %.0f deg about x: %zu polylines, the rulings at %.0f and %.0f deg within %.3f deg\n",
           SLOPE, count, rulings[0], rulings[1], worst);
    free(offsets);
    free(points);
    lml_curves_free(curves);
}

void test_slope(const Cylinder *c)
{
    LmlMesh *mesh = NULL;
    CHECK_STATUS(lml_mesh_new(c->xyz, c->vertex_count, c->triangles, c->triangle_count, &mesh), LML_STATUS_OK);
    if (mesh == NULL) {
        return;
    }
    invalid_inputs(mesh, c->vertex_count);
    helices(mesh, c);
    reachable_boundary(mesh);
    lml_mesh_free(mesh);
}
