/* Shading designs through the C ABI (paper Sec. 6) on a small south-facing vertical facade
 * (the plane y = 0, north +y, up +z): the noon sun of late June blocked by strips whose planes
 * end orthogonal to it (θ = 90° ± the noon elevation), the sun-path check's blocked fraction
 * near 1, the same from a given start field (a tilted height), the strips' verdict status on a
 * twisted facade whose curves are no P-curves of one angle, and every invalid input named. */
#include "check.h"
#include "harness.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* 6 x 6 cells over 4 m x 4 m: 49 vertices (the harness runs under valgrind). */
#define FACADE_CELLS 6
#define FACADE_SIZE 4.0
#define FACADE_VERTICES ((FACADE_CELLS + 1) * (FACADE_CELLS + 1))
#define FACADE_TRIANGLES (2 * FACADE_CELLS * FACADE_CELLS)
#define SHADING_BUDGET 60
#define SHADING_STRIPS 6

/* The facade y = twist * x * z over [-2, 2]^2 (the plane for twist 0). */
static LmlMesh *facade(double twist)
{
    double xyz[3 * FACADE_VERTICES];
    uint32_t triangles[3 * FACADE_TRIANGLES];
    LmlMesh *mesh = NULL;
    int i, j, t = 0;
    for (j = 0; j <= FACADE_CELLS; j++) {
        for (i = 0; i <= FACADE_CELLS; i++) {
            double x = -0.5 * FACADE_SIZE + FACADE_SIZE * i / FACADE_CELLS;
            double z = -0.5 * FACADE_SIZE + FACADE_SIZE * j / FACADE_CELLS;
            int v = j * (FACADE_CELLS + 1) + i;
            xyz[3 * v] = x;
            xyz[3 * v + 1] = twist * x * z;
            xyz[3 * v + 2] = z;
        }
    }
    for (j = 0; j < FACADE_CELLS; j++) {
        for (i = 0; i < FACADE_CELLS; i++) {
            uint32_t a = (uint32_t)(j * (FACADE_CELLS + 1) + i), b = a + 1, c = a + FACADE_CELLS + 2, d = a + FACADE_CELLS + 1;
            uint32_t quad[6] = {a, d, c, a, c, b};
            memcpy(&triangles[6 * t++], quad, sizeof quad);
        }
    }
    CHECK_STATUS(lml_mesh_new(xyz, FACADE_VERTICES, triangles, FACADE_TRIANGLES, &mesh), LML_STATUS_OK);
    return mesh;
}

/* Late June, noon +- 30 min true solar time, at 47.4 degrees north. */
static LmlShadingSite noon_site(void)
{
    LmlShadingSite site;
    CHECK_STATUS(lml_shading_site_default(&site), LML_STATUS_OK);
    site.first_month = 6;
    site.first_day = 14;
    site.last_month = 6;
    site.last_day = 28;
    site.first_hour = site.pass_first_hour = 11.5;
    site.last_hour = site.pass_last_hour = 12.5;
    return site;
}

/* A design stepped to convergence (or the budget) from the library's start (`start` NULL) or from
 * `start` (FACADE_VERTICES values); NULL when it could not be created. */
static LmlShading *solved(const LmlMesh *mesh, const LmlShadingSite *site, const uint32_t *labels, const double *start)
{
    LmlShading *shading = NULL;
    LmlShadingReport report;
    LmlStatus status = LML_STATUS_MORE;
    unsigned steps = 0;
    if (start == NULL) {
        CHECK_STATUS(lml_shading_new(mesh, site, labels, FACADE_VERTICES, 0, &shading), LML_STATUS_OK);
    } else {
        CHECK_STATUS(lml_shading_new_from_field(mesh, site, labels, FACADE_VERTICES, 0, start, &shading), LML_STATUS_OK);
    }
    while (shading != NULL && status == LML_STATUS_MORE && steps < SHADING_BUDGET / 10) {
        status = lml_shading_step(shading, 10, &report);
        steps++;
    }
    CHECK(status == LML_STATUS_MORE || status == LML_STATUS_CONVERGED);
    return shading;
}

static void invalid_inputs(const LmlMesh *mesh, const uint32_t *labels)
{
    LmlShading *shading = NULL;
    LmlShadingSite site = noon_site(), bad;
    uint32_t wrong[FACADE_VERTICES];
    CHECK_STATUS(lml_shading_site_default(NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_shading_new(NULL, &site, labels, FACADE_VERTICES, 0, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("mesh");
    CHECK(shading == NULL);
    CHECK_STATUS(lml_shading_new(mesh, NULL, labels, FACADE_VERTICES, 0, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("site");
    CHECK_STATUS(lml_shading_new(mesh, &site, NULL, FACADE_VERTICES, 0, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("labels");
    CHECK_STATUS(lml_shading_new(mesh, &site, labels, FACADE_VERTICES - 1, 0, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("labels for 49 vertices");
    CHECK_STATUS(lml_shading_new(mesh, &site, labels, FACADE_VERTICES, 0, NULL), LML_STATUS_INVALID_ARGUMENT);
    bad = site;
    bad.latitude_degrees = NAN;
    CHECK_STATUS(lml_shading_new(mesh, &bad, labels, FACADE_VERTICES, 0, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("latitude");
    bad = site;
    bad.first_month = 13;
    CHECK_STATUS(lml_shading_new(mesh, &bad, labels, FACADE_VERTICES, 0, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("month");
    bad = site;
    bad.north[0] = 0.0;
    bad.north[1] = 0.0;
    bad.north[2] = 1.0;
    CHECK_STATUS(lml_shading_new(mesh, &bad, labels, FACADE_VERTICES, 0, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("north");
    bad = site;
    bad.direct_region = 1;
    bad.delta_degrees[0] = 10.0;
    bad.delta_degrees[1] = -10.0;
    CHECK_STATUS(lml_shading_new(mesh, &bad, labels, FACADE_VERTICES, 0, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("delta");
    memcpy(wrong, labels, sizeof wrong);
    wrong[7] = 3;
    CHECK_STATUS(lml_shading_new(mesh, &site, wrong, FACADE_VERTICES, 0, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("labels[7]");
    {
        int v;
        for (v = 0; v < FACADE_VERTICES; v++) {
            wrong[v] = LML_SHADING_FREE;
        }
    }
    CHECK_STATUS(lml_shading_new(mesh, &site, wrong, FACADE_VERTICES, 0, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("free");
    CHECK_STATUS(lml_shading_new(mesh, &site, labels, FACADE_VERTICES, 101, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("ring");
    CHECK(shading == NULL);
    CHECK_STATUS(lml_shading_step(NULL, 1, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_shading_report(NULL, NULL), LML_STATUS_INVALID_ARGUMENT);
    lml_shading_free(NULL);
}

/* The largest angle in degrees between a level curve and the horizontal over the interior vertices
 * of the plane facade (central differences of `values` along x and z; the grid is square). */
static double level_tilt_degrees(const double *values)
{
    double tilt = 0.0;
    int i, j;
    for (j = 1; j < FACADE_CELLS; j++) {
        for (i = 1; i < FACADE_CELLS; i++) {
            int v = j * (FACADE_CELLS + 1) + i;
            double along_x = fabs(values[v + 1] - values[v - 1]), along_z = fabs(values[v + FACADE_CELLS + 1] - values[v - FACADE_CELLS - 1]);
            double angle = atan2(along_x, along_z) * 180.0 / acos(-1.0);
            tilt = angle > tilt ? angle : tilt;
        }
    }
    return tilt;
}

/* What a design on the plane facade must give against the noon sun: strips along at least
 * SHADING_STRIPS - 1 level curves, each strip's theta within 5 degrees of 90 -+ the noon elevation,
 * and the sun-path check blocking the block region's direct-sun hours (fraction at least 0.9, the
 * mean of its vertices' fractions). `name` labels the printed line. */
static void check_noon_blocking(LmlShading *shading, const uint32_t *labels, const char *name)
{
    LmlStrips *strips = NULL;
    LmlShadingReport report;
    LmlSunPathSummary summary;
    double values[FACADE_VERTICES], thetas[4 * SHADING_STRIPS];
    size_t needed = 0, k, strip_count = 0, reached = 0;
    double sum = 0.0;
    int v;
    CHECK_STATUS(lml_shading_report(shading, &report), LML_STATUS_OK);
    CHECK_STATUS(lml_shading_strips(shading, SHADING_STRIPS, 1.5, 2.0, &strips), LML_STATUS_OK);
    CHECK(strips != NULL);
    if (strips == NULL) {
        return;
    }
    CHECK_STATUS(lml_strips_count(strips, &strip_count), LML_STATUS_OK);
    CHECK(strip_count >= SHADING_STRIPS - 1);
    CHECK_STATUS(lml_shading_thetas(shading, thetas, 4 * SHADING_STRIPS, &needed), LML_STATUS_OK);
    CHECK(needed == strip_count);
    /* A plane orthogonal to the noon sun (elevation 90 - 47.4 + 23.4 = 66 degrees) that holds
     * the horizontal curve tangent meets the facade's normal at 90 -+ 66 degrees. */
    for (k = 0; k < needed; k++) {
        CHECK(fabs(thetas[k] - 156.0) < 5.0 || fabs(thetas[k] - 24.0) < 5.0);
    }

    /* The sun-path check. */
    CHECK_STATUS(lml_shading_evaluate(shading, strips, 0.0, &summary), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("offset");
    CHECK_STATUS(lml_shading_evaluate(shading, NULL, 0.05, &summary), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("strips");
    CHECK_STATUS(lml_shading_vertex_fractions(shading, values, FACADE_VERTICES, &needed), LML_STATUS_OK);
    CHECK(needed == 0);
    CHECK_STATUS(lml_shading_evaluate(shading, strips, 0.05, &summary), LML_STATUS_OK);
    /* 15 days x the hours 11.5, 12.5 (every hour from the first, and the last). */
    CHECK(summary.block_suns == 30 && summary.pass_suns == 30);
    printf("  shading (%s): %u iterations, %zu strips, theta[0] %.2f deg, blocked fraction %.3f\n", name, (unsigned)report.iterations, strip_count,
           strip_count > 0 ? thetas[0] : NAN, summary.block_fraction);
    CHECK(summary.block_fraction >= 0.9 && summary.block_fraction <= 1.0);
    CHECK(summary.pass_fraction == -1.0 && summary.free_fraction >= 0.0 && summary.free_fraction <= 1.0);
    CHECK(summary.rays == 2 * 30 * FACADE_VERTICES);
    CHECK_STATUS(lml_shading_vertex_fractions(shading, values, FACADE_VERTICES, &needed), LML_STATUS_OK);
    CHECK(needed == FACADE_VERTICES);
    for (v = 0; v < FACADE_VERTICES; v++) {
        CHECK(values[v] >= 0.0 && values[v] <= 1.0);
        if (labels[v] == LML_SHADING_BLOCK) {
            sum += values[v];
            reached++;
        }
    }
    /* Every sample sees the same suns on a plane: the region's fraction is its vertices' mean. */
    CHECK(reached == (FACADE_CELLS - 1) * (FACADE_CELLS - 1) && fabs(sum / reached - summary.block_fraction) < 1e-12);
    lml_strips_free(strips);
}

/* A design from a given start field: the height z tilted by a quarter of x (level curves at 14
 * degrees to the horizontal, not the default start's constant-slope family): the session's field
 * before any step is that start (up to the rounding of the solver's internal scaling, f * s / s:
 * within 2 ulp of the start's largest magnitude), and the report says no constant-slope start;
 * stepped, it meets the default start's expectations (check_noon_blocking), and its level curves
 * turn towards the horizontal until they are orthogonal to some sun of the hours: a tangent
 * (cos a, 0, sin a) of the facade is orthogonal to the sun (east, north, up) when
 * tan a = -east / up, so the hours 11.5 to 12.5 (hour angle H within 7.5 degrees) admit
 * |a| <= atan(cos d sin H / (sin d sin p + cos d cos H cos p)) = 7.5 degrees at latitude p 47.4
 * and declination d 23 (a smaller d of the dates' 23.2 to 23.4 gives a larger bound); 0.5 degrees
 * more for the central differences. `default_tilt`: the default start's result, printed beside.
 * Invalid starts are refused, named, with no session. */
static void from_field(const LmlMesh *mesh, const uint32_t *labels, double default_tilt)
{
    LmlShading *shading = NULL;
    LmlShadingSite site = noon_site();
    LmlShadingReport report;
    double start[FACADE_VERTICES], bad[FACADE_VERTICES], values[FACADE_VERTICES];
    uint32_t wrong[FACADE_VERTICES];
    size_t needed = 0;
    const double degree = acos(-1.0) / 180.0, p = 47.4 * degree, d = 23.0 * degree, h = 7.5 * degree;
    const double admitted = atan(cos(d) * sin(h) / (sin(d) * sin(p) + cos(d) * cos(h) * cos(p))) / degree;
    double largest = 0.0, deviation = 0.0, tilt;
    int v;
    for (v = 0; v < FACADE_VERTICES; v++) {
        double x = -0.5 * FACADE_SIZE + FACADE_SIZE * (v % (FACADE_CELLS + 1)) / FACADE_CELLS;
        double z = -0.5 * FACADE_SIZE + FACADE_SIZE * (v / (FACADE_CELLS + 1)) / FACADE_CELLS;
        start[v] = z + 0.25 * x;
        largest = fabs(start[v]) > largest ? fabs(start[v]) : largest;
    }

    /* Invalid starts: named, no session. */
    CHECK_STATUS(lml_shading_new_from_field(mesh, &site, labels, FACADE_VERTICES, 0, NULL, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("start_field");
    CHECK(shading == NULL);
    memcpy(bad, start, sizeof bad);
    bad[11] = NAN;
    CHECK_STATUS(lml_shading_new_from_field(mesh, &site, labels, FACADE_VERTICES, 0, bad, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("start_field");
    CHECK_MESSAGE("vertex 11");
    CHECK(shading == NULL);
    bad[11] = start[11];
    bad[30] = -INFINITY;
    CHECK_STATUS(lml_shading_new_from_field(mesh, &site, labels, FACADE_VERTICES, 0, bad, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("vertex 30");
    bad[30] = 1e101;
    CHECK_STATUS(lml_shading_new_from_field(mesh, &site, labels, FACADE_VERTICES, 0, bad, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("vertex 30");
    CHECK(shading == NULL);
    for (v = 0; v < FACADE_VERTICES; v++) {
        bad[v] = 1.5;
    }
    CHECK_STATUS(lml_shading_new_from_field(mesh, &site, labels, FACADE_VERTICES, 0, bad, &shading), LML_STATUS_SINGULAR_FIELD);
    CHECK_MESSAGE("start_field");
    CHECK_MESSAGE("constant");
    CHECK(shading == NULL);
    /* The other arguments are checked as by lml_shading_new. */
    CHECK_STATUS(lml_shading_new_from_field(mesh, &site, labels, FACADE_VERTICES - 1, 0, start, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("labels for 49 vertices");
    memcpy(wrong, labels, sizeof wrong);
    wrong[7] = 3;
    CHECK_STATUS(lml_shading_new_from_field(mesh, &site, wrong, FACADE_VERTICES, 0, start, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("labels[7]");
    CHECK_STATUS(lml_shading_new_from_field(mesh, &site, labels, FACADE_VERTICES, 101, start, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("ring");
    CHECK_STATUS(lml_shading_new_from_field(NULL, &site, labels, FACADE_VERTICES, 0, start, &shading), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("mesh");
    CHECK_STATUS(lml_shading_new_from_field(mesh, &site, labels, FACADE_VERTICES, 0, start, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK(shading == NULL);

    /* Before any step the field is the start; no constant-slope start. */
    CHECK_STATUS(lml_shading_new_from_field(mesh, &site, labels, FACADE_VERTICES, 0, start, &shading), LML_STATUS_OK);
    if (shading == NULL) {
        return;
    }
    CHECK_STATUS(lml_shading_field(shading, values, FACADE_VERTICES, &needed), LML_STATUS_OK);
    CHECK(needed == FACADE_VERTICES);
    for (v = 0; v < FACADE_VERTICES; v++) {
        double d = fabs(values[v] - start[v]);
        deviation = d > deviation ? d : deviation;
    }
    printf("  shading (given start): field before any step within %.1e of the start (largest |value| %.2f)\n", deviation, largest);
    CHECK(deviation <= 2.0 * DBL_EPSILON * largest);
    CHECK_STATUS(lml_shading_report(shading, &report), LML_STATUS_OK);
    CHECK(report.iterations == 0 && report.constant_slope_start == 0 && report.start_slope_degrees == 0.0);
    CHECK(report.block_vertices == (FACADE_CELLS - 1) * (FACADE_CELLS - 1));
    lml_shading_free(shading);

    /* Stepped: the default start's expectations, the level curves turned horizontal. */
    shading = solved(mesh, &site, labels, start);
    if (shading == NULL) {
        return;
    }
    CHECK_STATUS(lml_shading_field(shading, values, FACADE_VERTICES, &needed), LML_STATUS_OK);
    tilt = level_tilt_degrees(values);
    printf("  shading (given start): level curves from %.2f to %.2f deg off the horizontal (the hours admit %.2f; default start: %.2f deg)\n",
           level_tilt_degrees(start), tilt, admitted, default_tilt);
    CHECK(tilt <= admitted + 0.5);
    check_noon_blocking(shading, labels, "given start");
    lml_shading_free(shading);
}

void test_shading(void)
{
    LmlMesh *mesh = facade(0.0), *twisted = facade(0.4);
    LmlShading *shading = NULL, *twisted_shading = NULL;
    LmlStrips *strips = NULL, *twisted_strips = NULL;
    LmlShadingSite site = noon_site();
    LmlShadingReport report;
    uint32_t labels[FACADE_VERTICES];
    double values[FACADE_VERTICES], default_tilt;
    size_t needed = 0;
    int v;
    /* The boundary is free: its samples see past the strips' ends and the top strip. */
    for (v = 0; v < FACADE_VERTICES; v++) {
        int i = v % (FACADE_CELLS + 1), j = v / (FACADE_CELLS + 1);
        int boundary = i == 0 || j == 0 || i == FACADE_CELLS || j == FACADE_CELLS;
        labels[v] = boundary ? LML_SHADING_FREE : LML_SHADING_BLOCK;
    }
    if (mesh == NULL || twisted == NULL) {
        lml_mesh_free(mesh);
        lml_mesh_free(twisted);
        return;
    }
    invalid_inputs(mesh, labels);

    shading = solved(mesh, &site, labels, NULL);
    if (shading == NULL) {
        lml_mesh_free(mesh);
        lml_mesh_free(twisted);
        return;
    }
    CHECK_STATUS(lml_shading_report(shading, &report), LML_STATUS_OK);
    CHECK(report.iterations > 0 && report.block_vertices > 0 && report.pass_vertices == 0);
    /* The slope vote on a vertical south facade near noon: tangents orthogonal to the sun are
     * horizontal, slope 0 up to half a 5 degree bin. */
    CHECK(report.constant_slope_start == 1 && fabs(report.start_slope_degrees) <= 2.5);
    CHECK(isfinite(report.energy_block) && isfinite(report.energy_total));
    CHECK_STATUS(lml_shading_field(shading, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == FACADE_VERTICES);
    CHECK_STATUS(lml_shading_field(shading, values, FACADE_VERTICES, &needed), LML_STATUS_OK);
    for (v = 0; v < FACADE_VERTICES; v++) {
        CHECK(isfinite(values[v]));
    }
    default_tilt = level_tilt_degrees(values);

    /* Strips: invalid parameters named, then the strips of the field. */
    CHECK_STATUS(lml_shading_strips(shading, 0, 1.5, 2.0, &strips), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("count");
    CHECK_STATUS(lml_shading_strips(shading, SHADING_STRIPS, NAN, 2.0, &strips), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("width");
    CHECK_STATUS(lml_shading_strips(shading, SHADING_STRIPS, 1.5, 0.0, &strips), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("tolerance_degrees");
    CHECK(strips == NULL);
    check_noon_blocking(shading, labels, "default start");

    from_field(mesh, labels, default_tilt);

    /* Twisted, the level curves are no P-curves of one angle: the strips miss their θ. */
    twisted_shading = solved(twisted, &site, labels, NULL);
    if (twisted_shading != NULL) {
        CHECK_STATUS(lml_shading_strips(twisted_shading, SHADING_STRIPS, 1.5, 2.0, &twisted_strips), LML_STATUS_NO_ACCEPTABLE_FAMILY);
        CHECK_MESSAGE("worst: strip");
        CHECK(twisted_strips != NULL);
    }
    lml_strips_free(twisted_strips);
    lml_shading_free(twisted_shading);
    lml_shading_free(shading);
    lml_mesh_free(mesh);
    lml_mesh_free(twisted);
}
