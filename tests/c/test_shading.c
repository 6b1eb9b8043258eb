/* Shading designs through the C ABI (paper Sec. 6) on a small south-facing vertical facade
 * (the plane y = 0, north +y, up +z): the noon sun of late June blocked by strips whose planes
 * end orthogonal to it (θ = 90° ± the noon elevation), the sun-path check's blocked fraction
 * near 1, the strips' verdict status on a twisted facade whose curves are no P-curves of one
 * angle, and every invalid input named. */
#include "check.h"
#include "harness.h"

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

static LmlShading *solved(const LmlMesh *mesh, const LmlShadingSite *site, const uint32_t *labels)
{
    LmlShading *shading = NULL;
    LmlShadingReport report;
    LmlStatus status = LML_STATUS_MORE;
    unsigned steps = 0;
    CHECK_STATUS(lml_shading_new(mesh, site, labels, FACADE_VERTICES, 0, &shading), LML_STATUS_OK);
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

void test_shading(void)
{
    LmlMesh *mesh = facade(0.0), *twisted = facade(0.4);
    LmlShading *shading = NULL, *twisted_shading = NULL;
    LmlStrips *strips = NULL, *twisted_strips = NULL;
    LmlShadingSite site = noon_site();
    LmlShadingReport report;
    LmlSunPathSummary summary;
    uint32_t labels[FACADE_VERTICES];
    double values[FACADE_VERTICES], thetas[4 * SHADING_STRIPS];
    size_t needed = 0, k, strip_count = 0, reached = 0;
    double sum = 0.0;
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

    shading = solved(mesh, &site, labels);
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

    /* Strips: invalid parameters named, then the strips of the field. */
    CHECK_STATUS(lml_shading_strips(shading, 0, 1.5, 2.0, &strips), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("count");
    CHECK_STATUS(lml_shading_strips(shading, SHADING_STRIPS, NAN, 2.0, &strips), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("width");
    CHECK_STATUS(lml_shading_strips(shading, SHADING_STRIPS, 1.5, 0.0, &strips), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("tolerance_degrees");
    CHECK(strips == NULL);
    CHECK_STATUS(lml_shading_strips(shading, SHADING_STRIPS, 1.5, 2.0, &strips), LML_STATUS_OK);
    CHECK(strips != NULL);
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
    printf("  shading: %u iterations, %zu strips, theta[0] %.2f deg, blocked fraction %.3f\n", (unsigned)report.iterations, strip_count, thetas[0], summary.block_fraction);
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

    /* Twisted, the level curves are no P-curves of one angle: the strips miss their θ. */
    twisted_shading = solved(twisted, &site, labels);
    if (twisted_shading != NULL) {
        CHECK_STATUS(lml_shading_strips(twisted_shading, SHADING_STRIPS, 1.5, 2.0, &twisted_strips), LML_STATUS_NO_ACCEPTABLE_FAMILY);
        CHECK_MESSAGE("worst: strip");
        CHECK(twisted_strips != NULL);
    }
    lml_strips_free(twisted_strips);
    lml_shading_free(twisted_shading);
    lml_strips_free(strips);
    lml_shading_free(shading);
    lml_mesh_free(mesh);
    lml_mesh_free(twisted);
}
