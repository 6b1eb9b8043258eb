#include "check.h"
#include "harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define THETA 60.0

static LmlCurves *poisoned(void)
{
    static int marker;
    return (LmlCurves *)(void *)&marker;
}

/* Runs the two-call pattern on a double array of the curves: size query, a buffer one too
 * small, then the real copy; checks the size against `expected` (unless it is 0) and returns
 * the malloc'd array (owned by the caller) or NULL. */
static double *curve_doubles(LmlStatus (*get)(const LmlCurves *, double *, size_t, size_t *), const LmlCurves *curves,
                             size_t expected, size_t *count)
{
    size_t needed = 0;
    double *values;
    CHECK_STATUS(get(curves, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(expected == 0 || needed == expected);
    CHECK_STATUS(get(curves, NULL, 0, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(get(NULL, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    values = malloc(needed * sizeof(double) + 1); /* + 1: never malloc(0) */
    if (values == NULL) {
        return NULL;
    }
    CHECK_STATUS(get(curves, values, needed - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_MESSAGE("needed");
    CHECK_STATUS(get(curves, values, needed, &needed), LML_STATUS_OK);
    *count = needed;
    return values;
}

/* The field's range, from its values. */
static void field_range(const LmlField *field, size_t n, double *lo, double *hi)
{
    double *values = malloc(n * sizeof(double));
    size_t i, needed = 0;
    *lo = 0.0;
    *hi = 0.0;
    if (values == NULL) {
        CHECK(!"out of memory");
        return;
    }
    CHECK_STATUS(lml_field_values(field, values, n, &needed), LML_STATUS_OK);
    *lo = *hi = values[0];
    for (i = 1; i < n; i++) {
        *lo = fmin(*lo, values[i]);
        *hi = fmax(*hi, values[i]);
    }
    free(values);
}

/* Expects lml_curves_new to fail with `expected`, reset *out to NULL and name `part`. */
static void expect_refused(const LmlField *field, const double *levels, size_t count, double spacing,
                           LmlStatus expected, const char *part, int line)
{
    LmlCurves *curves = poisoned();
    check_status(lml_curves_new(field, levels, count, spacing, &curves), expected, __FILE__, line, "lml_curves_new");
    check(curves == NULL, __FILE__, line, "out reset to NULL");
    check_message(part, __FILE__, line);
    lml_curves_free(curves);
}

static void bad_inputs(const LmlField *field, double lo, double hi)
{
    double levels[3];
    LmlCurves *curves = poisoned();
    size_t count = 0;
    levels[0] = lo + 0.25 * (hi - lo);
    levels[1] = lo + 0.5 * (hi - lo);
    levels[2] = lo + 0.75 * (hi - lo);

    expect_refused(NULL, levels, 3, 0.0, LML_STATUS_INVALID_ARGUMENT, "field", __LINE__);
    expect_refused(field, NULL, 3, 0.0, LML_STATUS_INVALID_ARGUMENT, "levels", __LINE__);
    expect_refused(field, levels, 0, 0.0, LML_STATUS_INVALID_ARGUMENT, "at least one level", __LINE__);
    expect_refused(field, NULL, 0, 0.0, LML_STATUS_INVALID_ARGUMENT, "at least one level", __LINE__);
    levels[1] = NAN;
    expect_refused(field, levels, 3, 0.0, LML_STATUS_INVALID_ARGUMENT, "level 1 is not finite", __LINE__);
    levels[1] = INFINITY;
    expect_refused(field, levels, 3, 0.0, LML_STATUS_INVALID_ARGUMENT, "level 1 is not finite", __LINE__);
    levels[1] = hi + 1.0;
    expect_refused(field, levels, 3, 0.0, LML_STATUS_INVALID_ARGUMENT, "outside the field's range", __LINE__);
    levels[1] = lo - 1.0;
    expect_refused(field, levels, 3, 0.0, LML_STATUS_INVALID_ARGUMENT, "outside the field's range", __LINE__);
    levels[1] = lo + 0.5 * (hi - lo);
    expect_refused(field, levels, 3, -1.0, LML_STATUS_INVALID_ARGUMENT, "spacing", __LINE__);
    expect_refused(field, levels, 3, NAN, LML_STATUS_INVALID_ARGUMENT, "spacing", __LINE__);
    expect_refused(field, levels, 3, INFINITY, LML_STATUS_INVALID_ARGUMENT, "spacing", __LINE__);
    CHECK_STATUS(lml_curves_new(field, levels, 3, 0.0, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("out");

    CHECK_STATUS(lml_curves_new_uniform(field, 0, 1.0, &curves), LML_STATUS_INVALID_ARGUMENT);
    CHECK(curves == NULL);
    CHECK_MESSAGE("at least one level");
    curves = poisoned();
    CHECK_STATUS(lml_curves_new_uniform(NULL, 3, 1.0, &curves), LML_STATUS_INVALID_ARGUMENT);
    CHECK(curves == NULL);
    CHECK_STATUS(lml_curves_new_uniform(field, 3, -0.5, &curves), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("spacing");
    CHECK_STATUS(lml_curves_new_uniform(field, 3, 1.0, NULL), LML_STATUS_INVALID_ARGUMENT);
    /* Sizes from the caller are bounded before anything is allocated (they used to abort the host). */
    curves = poisoned();
    CHECK_STATUS(lml_curves_new_uniform(field, (size_t)1 << (sizeof(size_t) > 4 ? 40 : 31), 0.0, &curves), LML_STATUS_INVALID_ARGUMENT);
    CHECK(curves == NULL);
    CHECK_MESSAGE("at most 10000");
    CHECK_STATUS(lml_curves_new_uniform(field, LML_MAX_LEVELS + 1, 0.0, &curves), LML_STATUS_INVALID_ARGUMENT);
    expect_refused(field, levels, 1, 1e-9, LML_STATUS_INVALID_ARGUMENT, "points", __LINE__);
    {
        double *many = malloc((LML_MAX_LEVELS + 1) * sizeof(double));
        size_t i;
        CHECK(many != NULL);
        if (many != NULL) {
            for (i = 0; i <= LML_MAX_LEVELS; i++) {
                many[i] = levels[1];
            }
            expect_refused(field, many, LML_MAX_LEVELS + 1, 0.0, LML_STATUS_INVALID_ARGUMENT, "10001 levels", __LINE__);
            free(many);
        }
    }

    CHECK_STATUS(lml_curves_count(NULL, &count), LML_STATUS_INVALID_ARGUMENT);
    lml_curves_free(NULL);
}

/* Level curves of the converged theta = 60 degree field: on the cylinder, open from boundary to
 * boundary, unit radial normals; with `resampled`, discrete binormals at 60 degrees to the
 * surface normal. (Unresampled polylines have a point on every crossed mesh edge, some only a
 * hair apart, so their discrete binormals follow the triangulation, not the curve.) */
static void check_geometry(const LmlCurves *curves, const double *asked, size_t asked_count, int resampled)
{
    size_t c = 0, i, p, k3 = 0, kn = 0, cl = 0, ck = 0;
    size_t *offsets;
    unsigned char *closed;
    double *points, *normals, *levels;
    double off_surface = 0.0, normal_error = 0.0, worst_angle = 0.0, sum_angle = 0.0;
    size_t angles = 0;
    int ordered = 1;

    CHECK_STATUS(lml_curves_count(curves, &c), LML_STATUS_OK);
    /* Each level crosses the patch once: the cylinder's level curves are not closed. */
    CHECK(c == asked_count);
    offsets = malloc((c + 1) * sizeof(size_t));
    closed = malloc(c + 1);
    if (offsets == NULL || closed == NULL) {
        CHECK(!"out of memory");
        free(offsets);
        free(closed);
        return;
    }
    CHECK_STATUS(lml_curves_offsets(curves, NULL, 0, &ck), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(ck == c + 1);
    CHECK_STATUS(lml_curves_offsets(curves, offsets, c, &ck), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_curves_offsets(curves, offsets, c + 1, &ck), LML_STATUS_OK);
    CHECK_STATUS(lml_curves_closed(curves, closed, c - 1, &ck), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_curves_closed(curves, closed, c, &ck), LML_STATUS_OK);
    CHECK(ck == c);
    CHECK(offsets[0] == 0);
    for (i = 0; i < c; i++) {
        ordered = ordered && offsets[i + 1] >= offsets[i] + 3 && closed[i] == 0;
    }
    CHECK(ordered);

    points = curve_doubles(lml_curves_points, curves, 3 * offsets[c], &k3);
    normals = curve_doubles(lml_curves_normals, curves, 3 * offsets[c], &kn);
    levels = curve_doubles(lml_curves_levels, curves, c, &cl);
    if (points == NULL || normals == NULL || levels == NULL) {
        CHECK(!"out of memory");
    } else {
        for (i = 0; i < c; i++) {
            CHECK(levels[i] == asked[i]);
            for (p = offsets[i]; p < offsets[i + 1]; p++) {
                const double *x = points + 3 * p, *n = normals + 3 * p;
                double r = sqrt(x[0] * x[0] + x[1] * x[1]);
                off_surface = fmax(off_surface, fabs(r - CYLINDER_RADIUS));
                normal_error = fmax(normal_error, fabs(n[0] * x[0] / r + n[1] * x[1] / r - 1.0));
                if (p > offsets[i] && p + 1 < offsets[i + 1]) {
                    double error = fabs(cylinder_binormal_angle(x - 3, x, x + 3) - THETA);
                    worst_angle = fmax(worst_angle, error);
                    sum_angle += error;
                    angles++;
                }
            }
        }
        printf("  curves: %lu polylines, %lu points; max |r - R| = %.2e, max normal error %.2e, "
               "binormal angle error mean %.2f max %.2f deg\n",
               (unsigned long)c, (unsigned long)offsets[c], off_surface, normal_error,
               angles ? sum_angle / (double)angles : 0.0, worst_angle);
        /* Points lie on the mesh, whose chords deviate from the cylinder by at most the sagitta
         * h^2 / (8 R) of an edge (h <= 1.6 here: 0.032). */
        CHECK(off_surface < 0.04);
        /* Interpolated vertex normals against the analytic radial normal: a boundary vertex
         * normal averages the faces on one side only, off by up to half the angle between
         * neighbouring faces, h / (2 R) = 2.9 degrees for h = 1 (more where jittered): allow 4. */
        CHECK(normal_error < 1.0 - cos(4.0 * PI / 180.0));
        CHECK(angles > 0);
        /* Resampled level polylines of the 60 degree field (before any strip optimisation) are
         * pseudo-geodesics up to the field's discretisation: within 3 degrees on average (the
         * worst inner point is printed, not checked: it follows the mesh's kinks). */
        CHECK(!resampled || sum_angle / (double)(angles ? angles : 1) < 3.0);
    }
    free(points);
    free(normals);
    free(levels);
    free(offsets);
    free(closed);
}

LmlCurves *test_curves(const LmlField *field, const Cylinder *c)
{
    double lo, hi, levels[3];
    LmlCurves *raw = NULL, *uniform = NULL, *restored = NULL;
    LmlField *copy = NULL;
    uint8_t *bytes;
    double *a = NULL, *b = NULL;
    size_t i, na = 0, nb = 0, size = 0;

    field_range(field, c->vertex_count, &lo, &hi);
    bad_inputs(field, lo, hi);
    for (i = 0; i < 3; i++) {
        levels[i] = lo + (hi - lo) * (double)(i + 1) / 4.0;
    }

    /* Without resampling: one point per crossed mesh edge. */
    CHECK_STATUS(lml_curves_new(field, levels, 3, 0.0, &raw), LML_STATUS_OK);
    check_geometry(raw, levels, 3, 0);

    /* Uniform levels are the same values; resampled at spacing 1 the curves keep their shape. */
    CHECK_STATUS(lml_curves_new_uniform(field, 3, 1.0, &uniform), LML_STATUS_OK);
    check_geometry(uniform, levels, 3, 1);
    lml_curves_free(raw);

    /* A session restored from its saved bytes yields the same curves, bit for bit, and the
     * curves outlive the session they came from. */
    CHECK_STATUS(lml_field_save(field, NULL, 0, &size), LML_STATUS_BUFFER_TOO_SMALL);
    bytes = malloc(size);
    if (bytes != NULL) {
        CHECK_STATUS(lml_field_save(field, bytes, size, &size), LML_STATUS_OK);
        CHECK_STATUS(lml_field_load(bytes, size, &copy), LML_STATUS_OK);
        free(bytes);
    }
    CHECK_STATUS(lml_curves_new_uniform(copy, 3, 1.0, &restored), LML_STATUS_OK);
    lml_field_free(copy);
    a = curve_doubles(lml_curves_points, uniform, 0, &na);
    b = curve_doubles(lml_curves_points, restored, 0, &nb);
    CHECK(a != NULL && b != NULL && na == nb && na > 0 && memcmp(a, b, na * sizeof(double)) == 0);
    free(a);
    free(b);
    lml_curves_free(restored);
    return uniform;
}
