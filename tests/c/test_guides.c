/* Guide curves (paper Sec. 3.2.1) and the initial fields of Sec. 3.2.2 through the C ABI, on
 * the harness cylinder. In its development (s = R phi, z) the P-curves of angle theta are
 * catenaries z = z0 +- (cosh(k (s - s0)) - 1) / k, k = tan(90 - theta) / R (see
 * tests/integration/tracing_cylinder.rs); the boundary loop runs counter-clockwise in the development
 * (bottom left to right, right side up, top right to left, left side down). */
#include "check.h"
#include "harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define THETA 60.0
#define WIDTH (CYLINDER_RADIUS * CYLINDER_SPAN_DEGREES * PI / 180.0)
/* Guides of the parallel family, evenly spaced on the left side. */
#define GUIDES 4

/* The arrays of a guides handle. */
typedef struct {
    size_t count;
    size_t *offsets;       /* count + 1 */
    double *points;        /* 3 per point */
    LmlEdgePoint *edges;   /* 1 per point */
    LmlTraceStop *stops;   /* 1 per curve */
    double *lengths;       /* 1 per curve */
} Polylines;

static LmlGuides *poisoned(void)
{
    static int marker;
    return (LmlGuides *)(void *)&marker;
}

static void polylines_free(Polylines *p)
{
    free(p->offsets);
    free(p->points);
    free(p->edges);
    free(p->stops);
    free(p->lengths);
    memset(p, 0, sizeof *p);
}

/* Reads every array of `guides` with the two-call pattern (size query, one too small, copy). */
static int read_guides(const LmlGuides *guides, Polylines *p)
{
    size_t needed = 0, k;
    memset(p, 0, sizeof *p);
    CHECK_STATUS(lml_guides_count(guides, &p->count), LML_STATUS_OK);
    CHECK_STATUS(lml_guides_offsets(guides, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == p->count + 1);
    p->offsets = malloc(needed * sizeof(size_t));
    if (p->offsets == NULL) {
        return 0;
    }
    CHECK_STATUS(lml_guides_offsets(guides, p->offsets, needed - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_guides_offsets(guides, p->offsets, needed, &needed), LML_STATUS_OK);
    k = p->offsets[p->count];
    p->points = malloc(3 * k * sizeof(double));
    p->edges = malloc(k * sizeof(LmlEdgePoint));
    p->stops = malloc(p->count * sizeof(LmlTraceStop));
    p->lengths = malloc(p->count * sizeof(double));
    if (p->points == NULL || p->edges == NULL || p->stops == NULL || p->lengths == NULL) {
        polylines_free(p);
        return 0;
    }
    CHECK_STATUS(lml_guides_points(guides, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == 3 * k);
    CHECK_STATUS(lml_guides_points(guides, p->points, 3 * k - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_MESSAGE("needed");
    CHECK_STATUS(lml_guides_points(guides, p->points, 3 * k, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_guides_edge_points(guides, p->edges, k - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == k);
    CHECK_STATUS(lml_guides_edge_points(guides, p->edges, k, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_guides_stops(guides, p->stops, p->count - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_guides_stops(guides, p->stops, p->count, &needed), LML_STATUS_OK);
    CHECK(needed == p->count);
    CHECK_STATUS(lml_guides_lengths(guides, p->lengths, p->count - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_guides_lengths(guides, p->lengths, p->count, &needed), LML_STATUS_OK);
    CHECK(needed == p->count);
    return 1;
}

/* Angle-weighted vertex normals of the mesh (3 per vertex), computed here from the triangles. */
static double *mesh_normals(const Cylinder *c)
{
    double *n = calloc(3 * c->vertex_count, sizeof(double));
    size_t f, v;
    int k, d;
    if (n == NULL) {
        return NULL;
    }
    for (f = 0; f < c->triangle_count; f++) {
        const uint32_t *t = c->triangles + 3 * f;
        const double *p0 = c->xyz + 3 * t[0], *p1 = c->xyz + 3 * t[1], *p2 = c->xyz + 3 * t[2];
        double e1[3], e2[3], fn[3], l;
        for (d = 0; d < 3; d++) {
            e1[d] = p1[d] - p0[d];
            e2[d] = p2[d] - p0[d];
        }
        fn[0] = e1[1] * e2[2] - e1[2] * e2[1];
        fn[1] = e1[2] * e2[0] - e1[0] * e2[2];
        fn[2] = e1[0] * e2[1] - e1[1] * e2[0];
        l = sqrt(fn[0] * fn[0] + fn[1] * fn[1] + fn[2] * fn[2]);
        for (k = 0; k < 3; k++) {
            const double *a = c->xyz + 3 * t[k], *b = c->xyz + 3 * t[(k + 1) % 3], *e = c->xyz + 3 * t[(k + 2) % 3];
            double u[3], w[3], uw = 0.0, uu = 0.0, ww = 0.0, angle;
            for (d = 0; d < 3; d++) {
                u[d] = b[d] - a[d];
                w[d] = e[d] - a[d];
                uw += u[d] * w[d];
                uu += u[d] * u[d];
                ww += w[d] * w[d];
            }
            angle = acos(fmin(1.0, fmax(-1.0, uw / sqrt(uu * ww))));
            for (d = 0; d < 3; d++) {
                n[3 * t[k] + d] += angle * fn[d] / l;
            }
        }
    }
    for (v = 0; v < c->vertex_count; v++) {
        double *x = n + 3 * v, l = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        for (d = 0; d < 3; d++) {
            x[d] /= l;
        }
    }
    return n;
}

/* The mesh normal at an edge point, interpolated linearly along its edge. */
static void normal_at(const double *normals, LmlEdgePoint p, double n[3])
{
    double l;
    int d;
    for (d = 0; d < 3; d++) {
        n[d] = (1.0 - p.t) * normals[3 * p.a + d] + p.t * normals[3 * p.b + d];
    }
    l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (d = 0; d < 3; d++) {
        n[d] /= l;
    }
}

/* Whether the polyline does not turn at `p` (sine of the turn below 1e-9): no binormal. */
static int straight(const double *prev, const double *p, const double *next)
{
    double e0[3], e1[3], b[3], l0 = 0.0, l1 = 0.0;
    int d;
    for (d = 0; d < 3; d++) {
        e0[d] = p[d] - prev[d];
        e1[d] = next[d] - p[d];
        l0 += e0[d] * e0[d];
        l1 += e1[d] * e1[d];
    }
    b[0] = e0[1] * e1[2] - e0[2] * e1[1];
    b[1] = e0[2] * e1[0] - e0[0] * e1[2];
    b[2] = e0[0] * e1[1] - e0[1] * e1[0];
    return sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]) < 1e-9 * sqrt(l0 * l1);
}

/* Largest |binormal angle - theta| over the interior points of curve `i`, with the mesh normals;
 * `reversed`: measured travelling the curve backwards. Straight turns have no binormal and are
 * skipped, but at most one is accepted per curve (180 is returned otherwise): the tracer may
 * reach the boundary by an exactly straight last step. */
static double worst_angle_error(const Polylines *p, size_t i, const double *normals, double theta, int reversed)
{
    double worst = 0.0;
    size_t q, straight_turns = 0;
    for (q = p->offsets[i] + 1; q + 1 < p->offsets[i + 1]; q++) {
        const double *x = p->points + 3 * q;
        double n[3];
        if (straight(x - 3, x, x + 3)) {
            straight_turns++;
            continue;
        }
        normal_at(normals, p->edges[q], n);
        if (reversed) {
            worst = fmax(worst, fabs(binormal_angle(x + 3, x, x - 3, n) - theta));
        } else {
            worst = fmax(worst, fabs(binormal_angle(x - 3, x, x + 3, n) - theta));
        }
    }
    return straight_turns > 1 ? 180.0 : worst;
}

/* Development coordinates (s, z) of a point of the cylinder. */
static void develop(const double *x, double *s, double *z)
{
    *s = CYLINDER_RADIUS * atan2(x[1], x[0]);
    *z = x[2];
}

/* The position of an edge point from the mesh's coordinates. */
static void edge_point_position(const Cylinder *c, LmlEdgePoint p, double x[3])
{
    int d;
    for (d = 0; d < 3; d++) {
        x[d] = (1.0 - p.t) * c->xyz[3 * p.a + d] + p.t * c->xyz[3 * p.b + d];
    }
}

/* The boundary point nearest to the development point (s, z) pushed 0.5 outwards off the
 * surface (a click beside the patch), checked to lie on the boundary at (s, z). */
static LmlEdgePoint clicked_start(const LmlMesh *mesh, const Cylinder *c, double s, double z)
{
    LmlEdgePoint p = {0, 0, 0.0};
    double phi = s / CYLINDER_RADIUS, click[3], x[3];
    click[0] = (CYLINDER_RADIUS + 0.5) * cos(phi);
    click[1] = (CYLINDER_RADIUS + 0.5) * sin(phi);
    click[2] = z;
    CHECK_STATUS(lml_boundary_start_nearest(mesh, click, &p), LML_STATUS_OK);
    edge_point_position(c, p, x);
    CHECK(fabs(x[0] - CYLINDER_RADIUS * cos(phi)) < 1e-9 && fabs(x[1] - CYLINDER_RADIUS * sin(phi)) < 1e-9 &&
          fabs(x[2] - z) < 1e-9);
    return p;
}

/* The segment of boundary loop 0 whose starts lie on the side phi = 0 (s = 0). */
static uint32_t left_segment(const LmlMesh *mesh, const Cylinder *c)
{
    size_t count = 0, needed = 0;
    uint32_t i;
    CHECK_STATUS(lml_boundary_segment_count(mesh, 0, LML_DEFAULT_CORNER_TURN_DEGREES, &count), LML_STATUS_OK);
    /* The patch has four straight or circular sides meeting at right angles. */
    CHECK(count == 4);
    for (i = 0; i < count; i++) {
        LmlEdgePoint p;
        double x[3];
        CHECK_STATUS(lml_boundary_starts(mesh, 0, LML_DEFAULT_CORNER_TURN_DEGREES, i, 1, &p, 1, &needed), LML_STATUS_OK);
        edge_point_position(c, p, x);
        if (fabs(x[1]) < 1e-9) {
            return i;
        }
    }
    CHECK(!"no boundary segment on the side s = 0");
    return 0;
}

/* GUIDES evenly spaced starts on the left side, checked by arc length, sorted upwards. */
static void left_starts(const LmlMesh *mesh, const Cylinder *c, LmlEdgePoint starts[GUIDES])
{
    uint32_t segment = left_segment(mesh, c);
    size_t needed = 0, i;
    int spaced = 1;
    CHECK_STATUS(lml_boundary_starts(mesh, 0, LML_DEFAULT_CORNER_TURN_DEGREES, segment, GUIDES, NULL, 0, &needed),
                 LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == GUIDES);
    CHECK_STATUS(lml_boundary_starts(mesh, 0, LML_DEFAULT_CORNER_TURN_DEGREES, segment, GUIDES, starts, GUIDES - 1, &needed),
                 LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_boundary_starts(mesh, 0, LML_DEFAULT_CORNER_TURN_DEGREES, segment, GUIDES, starts, GUIDES, &needed),
                 LML_STATUS_OK);
    /* Loop order runs down the left side: start i is at (i + 1/2) H / GUIDES below the top
     * corner. Reversed, guide i lies below guide i + 1, so the field F = i grows upwards, to the
     * left of curves travelling in +s: the 60 degree family. */
    for (i = 0; i < GUIDES; i++) {
        double x[3];
        edge_point_position(c, starts[i], x);
        spaced = spaced && fabs(x[1]) < 1e-9 &&
                 fabs(x[2] - CYLINDER_HEIGHT * (1.0 - ((double)i + 0.5) / GUIDES)) < 1e-9;
    }
    CHECK(spaced);
    for (i = 0; i < GUIDES / 2; i++) {
        LmlEdgePoint swap = starts[i];
        starts[i] = starts[GUIDES - 1 - i];
        starts[GUIDES - 1 - i] = swap;
    }
}

/* The catenary of the 60 degree family in the development: apex height z0 at s0, opening up. */
static double catenary(double s, double s0, double z0)
{
    double k = tan((90.0 - THETA) * PI / 180.0) / CYLINDER_RADIUS;
    return z0 + (cosh(k * (s - s0)) - 1.0) / k;
}

/* Traced guides of the parallel family: geometry, stops, lengths, order. */
static void check_family(const LmlGuides *guides, const Cylinder *c, const double *normals, Polylines *p)
{
    double worst = 0.0, worst_length = 0.0, worst_position = 0.0, worst_curve = 0.0;
    size_t i, q;
    int stops = 1;
    CHECK(p->count == GUIDES);
    for (i = 0; i < p->count; i++) {
        double length = 0.0, s0, z0;
        develop(p->points + 3 * p->offsets[i], &s0, &z0);
        CHECK(p->offsets[i + 1] - p->offsets[i] > 8);
        worst = fmax(worst, worst_angle_error(p, i, normals, THETA, 0));
        stops = stops && p->stops[i] == LML_TRACE_STOP_BOUNDARY;
        for (q = p->offsets[i]; q < p->offsets[i + 1]; q++) {
            double x[3], s, z;
            edge_point_position(c, p->edges[q], x);
            worst_position = fmax(worst_position, fabs(x[0] - p->points[3 * q]) + fabs(x[1] - p->points[3 * q + 1]) +
                                                      fabs(x[2] - p->points[3 * q + 2]));
            develop(p->points + 3 * q, &s, &z);
            /* Started perpendicular to the side (alpha = 90): the apex is the start point. */
            worst_curve = fmax(worst_curve, fabs(z - catenary(s, 0.0, z0)));
            if (q > p->offsets[i]) {
                const double *a = p->points + 3 * q, *b = a - 3;
                length += sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
            }
        }
        worst_length = fmax(worst_length, fabs(length - p->lengths[i]));
    }
    printf("  guides: %lu curves, %lu points; binormal angle error max %.3f deg (mesh normals); "
           "max distance from the catenary %.3f\n",
           (unsigned long)p->count, (unsigned long)p->offsets[p->count], worst, worst_curve);
    CHECK(worst <= 1.0);
    CHECK(stops);
    CHECK(worst_position < 1e-12);
    CHECK(worst_length < 1e-9);
    /* The analytic P-curve through the start, up to the discretisation of the coarse mesh. */
    CHECK(worst_curve < 0.25);
    CHECK_STATUS(lml_guides_check_order(guides), LML_STATUS_OK);
}

/* The two crossings of z = L(s) (from the left side, 60 degrees, alpha = 60) and its copy
 * turned by 180 degrees about the patch's centre normal, z = H - L(W - s) (from the right
 * side): s in [0, W/2] and [W/2, W], by bisection of L(s) + L(W - s) - H. */
static void analytic_crossings(double s0, double zmin, double out[2])
{
    int side, k;
    for (side = 0; side < 2; side++) {
        double lo = side == 0 ? 0.0 : WIDTH / 2.0, hi = side == 0 ? WIDTH / 2.0 : WIDTH;
        for (k = 0; k < 100; k++) {
            double mid = 0.5 * (lo + hi);
            double g = catenary(mid, s0, zmin) + catenary(WIDTH - mid, s0, zmin) - CYLINDER_HEIGHT;
            /* g falls towards the middle: on the left half it is decreasing in s. */
            if ((g > 0.0) == (side == 0)) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        out[side] = 0.5 * (lo + hi);
    }
}

/* A curve of the 60 degree family and one of the 120 degree family (both traced at 60 degrees,
 * the second from the opposite side, so that travelled in the same direction as the first it
 * is a 120 degree curve) cross twice. */
static void check_crossings(const LmlMesh *mesh, const Cylinder *c, const double *normals)
{
    const double a = 7.0, k = tan((90.0 - THETA) * PI / 180.0) / CYLINDER_RADIUS;
    /* alpha = 60 from the left side (boundary direction down): the curve leaves at 30 degrees
     * below the circumference, so its apex lies at s0 with sinh(k s0) = tan 30. */
    const double s0 = asinh(tan(30.0 * PI / 180.0)) / k, zmin = a - (cosh(k * s0) - 1.0) / k;
    LmlEdgePoint starts[2];
    LmlGuides *guides = NULL;
    LmlCrossing crossings[4];
    Polylines p;
    size_t needed = 0, i;
    double expected[2];

    starts[0] = clicked_start(mesh, c, 0.0, a);
    starts[1] = clicked_start(mesh, c, WIDTH, CYLINDER_HEIGHT - a);
    CHECK_STATUS(lml_guides_trace(mesh, starts, 2, THETA, 60.0, NULL, &guides), LML_STATUS_OK);
    if (guides == NULL || !read_guides(guides, &p)) {
        CHECK(!"traced and read");
        lml_guides_free(guides);
        return;
    }
    printf("  60/120 degree pair: binormal angle errors %.3f and %.3f deg\n", worst_angle_error(&p, 0, normals, THETA, 0),
           worst_angle_error(&p, 1, normals, 180.0 - THETA, 1));
    CHECK(worst_angle_error(&p, 0, normals, THETA, 0) <= 1.0);
    CHECK(worst_angle_error(&p, 1, normals, 180.0 - THETA, 1) <= 1.0);

    CHECK_STATUS(lml_guides_crossings(guides, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == 2);
    CHECK_STATUS(lml_guides_crossings(guides, crossings, 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_guides_crossings(guides, crossings, 4, &needed), LML_STATUS_OK);
    analytic_crossings(s0, zmin, expected);
    for (i = 0; i < needed && i < 2; i++) {
        const LmlCrossing *x = crossings + i;
        double s, z, r = sqrt(x->position[0] * x->position[0] + x->position[1] * x->position[1]);
        int found = 0, j;
        develop(x->position, &s, &z);
        CHECK(x->first_curve == 0 && x->second_curve == 1);
        CHECK(x->first_segment + 1 < p.offsets[1] && p.offsets[1] + x->second_segment + 1 < p.offsets[2]);
        CHECK(fabs(r - CYLINDER_RADIUS) < 0.05);
        for (j = 0; j < 2; j++) {
            found = found || (fabs(s - expected[j]) < 0.3 && fabs(z - catenary(expected[j], s0, zmin)) < 0.3);
        }
        printf("  crossing %lu at (s, z) = (%.3f, %.3f); analytic s = %.3f or %.3f\n", (unsigned long)i, s, z,
               expected[0], expected[1]);
        CHECK(found);
    }
    CHECK_STATUS(lml_guides_check_order(guides), LML_STATUS_INVALID_GUIDES);
    CHECK_MESSAGE("guide curves 0 and 1 cross");
    polylines_free(&p);
    lml_guides_free(guides);
}

/* Max |F(p) - i| over the points p of guide i. */
static double interpolation_error(const Polylines *p, const double *field)
{
    double worst = 0.0;
    size_t i, q;
    for (i = 0; i < p->count; i++) {
        for (q = p->offsets[i]; q < p->offsets[i + 1]; q++) {
            LmlEdgePoint e = p->edges[q];
            worst = fmax(worst, fabs((1.0 - e.t) * field[e.a] + e.t * field[e.b] - (double)i));
        }
    }
    return worst;
}

/* The field from the guides interpolates them and leads the optimisation to the 60 degree family. */
static void check_guide_field(const LmlMesh *mesh, const LmlGuides *guides, const Cylinder *c, const Polylines *p)
{
    double *field = malloc(c->vertex_count * sizeof(double)), target = 0.0, error;
    size_t needed = 0;
    LmlFieldParams params;
    LmlField *session = NULL;
    LmlReport report;
    if (field == NULL) {
        CHECK(!"out of memory");
        return;
    }
    CHECK_STATUS(lml_field_values_from_guides(mesh, guides, NULL, 0, &needed, NULL), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == c->vertex_count);
    CHECK_STATUS(lml_field_values_from_guides(mesh, guides, field, needed, &needed, &target), LML_STATUS_OK);
    error = interpolation_error(p, field);
    printf("  guide field: interpolation error %.2e, gradient target %.4f\n", error, target);
    CHECK(error <= 0.02);
    /* Guides H / GUIDES = 3.75 apart along the axis: F ~ (z - catenary(s)) / 3.75, whose gradient
     * norm cosh(k s) / 3.75 grows from 0.267 at the left side to 0.39 where the top guide ends. */
    CHECK(target > 0.26 && target < 0.4);

    CHECK_STATUS(lml_field_params_default(LML_FAMILY_PSEUDO_GEODESIC, THETA, &params), LML_STATUS_OK);
    params.gradient_target = target;
    /* Default parameters: the angle term settles within about 25 iterations, and the solver
     * stops there (curve terms below 1e-7) instead of waiting for E_grad's slow redistribution
     * of the spacing. */
    CHECK_STATUS(lml_field_new(mesh, field, c->vertex_count, &params, &session), LML_STATUS_OK);
    CHECK_STATUS(lml_field_solve(session, 300, &report), LML_STATUS_CONVERGED);
    printf("  solved from the guide field: %lu iterations, max angle error %.3f deg\n",
           (unsigned long)report.iterations, report.angle_error_max_degrees);
    /* The report's measure along the level polylines reads 0.56 deg here since 3f04e84 (under
     * 0.5 before; see test_solve.c): 1 degree. */
    CHECK(report.angle_error_max_degrees <= 1.0);
    CHECK(report.singular_vertex_count == 0);
    lml_field_free(session);
    free(field);
}

/* Strokes drawn along the guides, lifted 0.05 off the surface along its normal. */
static void check_strokes(const LmlMesh *mesh, const Cylinder *c, const double *normals, const Polylines *p)
{
    size_t k = p->offsets[p->count], q, needed = 0;
    double *points = malloc(3 * k * sizeof(double)), *field = malloc(c->vertex_count * sizeof(double));
    double theta = 0.0;
    int d;
    if (points == NULL || field == NULL) {
        CHECK(!"out of memory");
        free(points);
        free(field);
        return;
    }
    for (q = 0; q < k; q++) {
        double n[3];
        normal_at(normals, p->edges[q], n);
        for (d = 0; d < 3; d++) {
            points[3 * q + d] = p->points[3 * q + d] + 0.05 * n[d];
        }
    }
    CHECK_STATUS(lml_field_values_from_strokes(mesh, points, k, p->offsets, p->count, NULL, 0, &needed, &theta),
                 LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == c->vertex_count);
    CHECK_STATUS(lml_field_values_from_strokes(mesh, points, k, p->offsets, p->count, field, needed, &needed, &theta),
                 LML_STATUS_OK);
    printf("  strokes along the guides: estimated theta %.3f deg\n", theta);
    CHECK(fabs(theta - THETA) <= 1.0);
    /* Without the angle: NULL is accepted. */
    CHECK_STATUS(lml_field_values_from_strokes(mesh, points, k, p->offsets, p->count, field, needed, &needed, NULL),
                 LML_STATUS_OK);
    free(points);
    free(field);
}

/* Every invalid input of the stroke initialisation, on two strokes along the guides 0 and 1. */
static void bad_strokes(const LmlMesh *mesh, const Polylines *p)
{
    size_t n0 = p->offsets[1], n1 = p->offsets[2] - p->offsets[1], k = n0 + n1, offsets[4], needed = 0;
    double *points = malloc(3 * (k + 1) * sizeof(double)), field[1], theta;
    if (points == NULL) {
        CHECK(!"out of memory");
        return;
    }
    memcpy(points, p->points, 3 * k * sizeof(double));
    offsets[0] = 0;
    offsets[1] = n0;
    offsets[2] = k;

    CHECK_STATUS(lml_field_values_from_strokes(mesh, points, n0, offsets, 1, field, 1, &needed, &theta), LML_STATUS_INVALID_STROKES);
    CHECK_MESSAGE("1 stroke(s) given");
    /* Stroke 1 as a copy of stroke 0: both pass through the same triangles. */
    offsets[1] = n0;
    offsets[2] = 2 * n0;
    {
        double *twice = malloc(6 * n0 * sizeof(double));
        if (twice != NULL) {
            memcpy(twice, p->points, 3 * n0 * sizeof(double));
            memcpy(twice + 3 * n0, p->points, 3 * n0 * sizeof(double));
            CHECK_STATUS(lml_field_values_from_strokes(mesh, twice, 2 * n0, offsets, 2, field, 1, &needed, &theta),
                         LML_STATUS_INVALID_STROKES);
            CHECK_MESSAGE("strokes 0 and 1 cross");
            free(twice);
        }
    }
    offsets[1] = n0;
    offsets[2] = k;
    /* Stroke 1, point 2: 5 off the surface (radially), then not finite. */
    points[3 * (n0 + 2)] *= 1.5;
    points[3 * (n0 + 2) + 1] *= 1.5;
    CHECK_STATUS(lml_field_values_from_strokes(mesh, points, k, offsets, 2, field, 1, &needed, &theta), LML_STATUS_INVALID_STROKES);
    CHECK_MESSAGE("stroke 1, point 2: farther than");
    points[3 * (n0 + 2) + 2] = NAN;
    CHECK_STATUS(lml_field_values_from_strokes(mesh, points, k, offsets, 2, field, 1, &needed, &theta), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("stroke 1, point 2: coordinate is not finite");
    memcpy(points + 3 * (n0 + 2), p->points + 3 * (n0 + 2), 3 * sizeof(double));
    /* Stroke 1 of a single point. */
    offsets[2] = n0 + 1;
    CHECK_STATUS(lml_field_values_from_strokes(mesh, points, n0 + 1, offsets, 2, field, 1, &needed, &theta),
                 LML_STATUS_INVALID_STROKES);
    CHECK_MESSAGE("stroke 1 has only 1 usable point");
    /* The offset table. */
    offsets[2] = k;
    offsets[0] = 1;
    CHECK_STATUS(lml_field_values_from_strokes(mesh, points, k, offsets, 2, field, 1, &needed, &theta), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("offsets[0] = 1 must be 0");
    offsets[0] = 0;
    offsets[2] = k + 1;
    CHECK_STATUS(lml_field_values_from_strokes(mesh, points, k, offsets, 2, field, 1, &needed, &theta), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("offsets[2]");
    offsets[1] = k;
    offsets[2] = n0;
    offsets[3] = k;
    CHECK_STATUS(lml_field_values_from_strokes(mesh, points, k, offsets, 3, field, 1, &needed, &theta), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("offsets[2]");
    CHECK_STATUS(lml_field_values_from_strokes(mesh, NULL, k, offsets, 2, field, 1, &needed, &theta), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("points");
    CHECK_STATUS(lml_field_values_from_strokes(mesh, points, k, NULL, 2, field, 1, &needed, &theta), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("offsets");
    CHECK_STATUS(lml_field_values_from_strokes(NULL, points, k, offsets, 2, field, 1, &needed, &theta), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("mesh");
    free(points);
}

/* Expects lml_guides_trace to fail with INVALID_ARGUMENT naming `part` and reset *out to NULL. */
static void expect_refused(const LmlMesh *mesh, const LmlEdgePoint *starts, size_t count, double theta, double alpha,
                           const LmlTraceOptions *options, const char *part, int line)
{
    LmlGuides *guides = poisoned();
    check_status(lml_guides_trace(mesh, starts, count, theta, alpha, options, &guides), LML_STATUS_INVALID_ARGUMENT,
                 __FILE__, line, "lml_guides_trace");
    check(guides == NULL, __FILE__, line, "out reset to NULL");
    check_message(part, __FILE__, line);
    lml_guides_free(guides);
}

/* Every invalid input of the starts and of tracing. */
static void bad_inputs(const LmlMesh *mesh, const Cylinder *c, const LmlEdgePoint *good)
{
    LmlTraceOptions options;
    LmlEdgePoint starts[2], p;
    size_t count = 0, needed = 0;
    double nan_point[3] = {NAN, 0.0, 1.0};
    LmlGuides *guides = NULL;

    CHECK_STATUS(lml_trace_options_default(NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("out");
    CHECK_STATUS(lml_boundary_segment_count(mesh, 1, 30.0, &count), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("boundary loop 1 does not exist (the mesh has 1)");
    CHECK_STATUS(lml_boundary_segment_count(mesh, 0, 200.0, &count), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("corner turning angle 200");
    CHECK_STATUS(lml_boundary_segment_count(mesh, 0, NAN, &count), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_boundary_segment_count(NULL, 0, 30.0, &count), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("mesh");
    CHECK_STATUS(lml_boundary_segment_count(mesh, 0, 30.0, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("count");
    CHECK_STATUS(lml_boundary_starts(mesh, 0, 30.0, 9, 3, starts, 2, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("boundary segment 9 does not exist (there are 4)");
    CHECK_STATUS(lml_boundary_starts(mesh, 0, 30.0, 0, 0, starts, 2, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("zero start points");
    /* A count from the caller is bounded before anything is allocated (it used to abort the host). */
    CHECK_STATUS(lml_boundary_starts(mesh, 0, 30.0, 0, UINT32_MAX, starts, 2, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("at most 10000");
    CHECK_STATUS(lml_boundary_starts(mesh, 0, 30.0, 0, LML_MAX_STARTS + 1, starts, 2, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_boundary_starts(mesh, 0, 30.0, 0, LML_MAX_STARTS, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == LML_MAX_STARTS);
    CHECK_STATUS(lml_boundary_starts(mesh, 0, 30.0, 0, 1, starts, 2, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("needed");
    CHECK_STATUS(lml_boundary_start_at(mesh, 0, 1.5, &p), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("s = 1.5");
    CHECK_STATUS(lml_boundary_start_at(mesh, 0, NAN, &p), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_boundary_start_at(mesh, 2, 0.5, &p), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("boundary loop 2");
    CHECK_STATUS(lml_boundary_start_at(mesh, 0, 0.5, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_boundary_start_nearest(mesh, nan_point, &p), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("argument `point`: query point has a NaN or infinite coordinate");
    CHECK_STATUS(lml_boundary_start_nearest(mesh, NULL, &p), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("point");
    /* s = 0 and s = 1 are the loop's first vertex; s = 1/2 is half way round. */
    {
        LmlEdgePoint p0, p1;
        double x0[3], x1[3];
        CHECK_STATUS(lml_boundary_start_at(mesh, 0, 0.0, &p0), LML_STATUS_OK);
        CHECK_STATUS(lml_boundary_start_at(mesh, 0, 1.0, &p1), LML_STATUS_OK);
        edge_point_position(c, p0, x0);
        edge_point_position(c, p1, x1);
        CHECK(fabs(x0[0] - x1[0]) + fabs(x0[1] - x1[1]) + fabs(x0[2] - x1[2]) < 1e-9);
    }

    CHECK_STATUS(lml_trace_options_default(&options), LML_STATUS_OK);
    CHECK(isinf(options.max_length) && options.max_length > 0.0 && options.max_points == 100000 &&
          options.angle_tolerance_degrees == 2.0 && options.max_turn_degrees == 45.0);
    starts[0] = good[0];
    starts[1] = good[1];
    expect_refused(mesh, starts, 0, THETA, 90.0, NULL, "at least one start point", __LINE__);
    expect_refused(NULL, starts, 2, THETA, 90.0, NULL, "mesh", __LINE__);
    expect_refused(mesh, NULL, 2, THETA, 90.0, NULL, "starts", __LINE__);
    expect_refused(mesh, starts, 2, 200.0, 90.0, NULL, "theta_degrees", __LINE__);
    expect_refused(mesh, starts, 2, NAN, 90.0, NULL, "theta_degrees", __LINE__);
    expect_refused(mesh, starts, 2, THETA, 0.0, NULL, "start_angle_degrees", __LINE__);
    expect_refused(mesh, starts, 2, THETA, 180.0, NULL, "start_angle_degrees", __LINE__);
    options.max_turn_degrees = 0.0;
    expect_refused(mesh, starts, 2, THETA, 90.0, &options, "`max_turn_degrees` = 0", __LINE__);
    options.max_turn_degrees = 45.0;
    options.max_points = 1;
    expect_refused(mesh, starts, 2, THETA, 90.0, &options, "`max_points` = 1", __LINE__);
    options.max_points = 100000;
    options.max_length = NAN;
    expect_refused(mesh, starts, 2, THETA, 90.0, &options, "argument `options`", __LINE__);
    options.max_length = INFINITY;
    options.angle_tolerance_degrees = 90.0;
    expect_refused(mesh, starts, 2, THETA, 90.0, &options, "angle_tolerance_degrees", __LINE__);
    options.angle_tolerance_degrees = 2.0;
    /* An interior edge: the first edge of the second row of the grid (vertices 27 and 28 of the
     * 26 x 15 harness cylinder) is shared by two triangles. */
    starts[1].a = 27;
    starts[1].b = 28;
    starts[1].t = 0.5;
    expect_refused(mesh, starts, 2, THETA, 90.0, NULL, "argument `starts[1]`: start point edge (27, 28) is not a boundary edge", __LINE__);
    starts[1] = good[1];
    starts[1].t = 1.5;
    expect_refused(mesh, starts, 2, THETA, 90.0, NULL, "starts[1]", __LINE__);
    starts[1].a = 100000;
    expect_refused(mesh, starts, 2, THETA, 90.0, NULL, "vertex 100000 is out of range", __LINE__);
    CHECK_STATUS(lml_guides_trace(mesh, good, 2, THETA, 90.0, NULL, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("out");

    /* The limits stop curves early. */
    options.max_points = 5;
    CHECK_STATUS(lml_guides_trace(mesh, good, 1, THETA, 90.0, &options, &guides), LML_STATUS_OK);
    {
        LmlTraceStop stop = 99;
        size_t offsets[2];
        CHECK_STATUS(lml_guides_stops(guides, &stop, 1, &needed), LML_STATUS_OK);
        CHECK_STATUS(lml_guides_offsets(guides, offsets, 2, &needed), LML_STATUS_OK);
        CHECK(stop == LML_TRACE_STOP_POINT_LIMIT && offsets[1] == 5);
    }
    lml_guides_free(guides);
    options.max_points = 100000;
    options.max_length = 3.0;
    CHECK_STATUS(lml_guides_trace(mesh, good, 1, THETA, 90.0, &options, &guides), LML_STATUS_OK);
    {
        LmlTraceStop stop = 99;
        double length = 0.0;
        CHECK_STATUS(lml_guides_stops(guides, &stop, 1, &needed), LML_STATUS_OK);
        CHECK_STATUS(lml_guides_lengths(guides, &length, 1, &needed), LML_STATUS_OK);
        CHECK(stop == LML_TRACE_STOP_LENGTH_LIMIT && length >= 3.0 && length < 5.0);
    }
    lml_guides_free(guides);

    CHECK_STATUS(lml_guides_count(NULL, &count), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("guides");
    CHECK_STATUS(lml_guides_offsets(NULL, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_guides_points(NULL, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_guides_edge_points(NULL, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_guides_stops(NULL, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_guides_lengths(NULL, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_guides_crossings(NULL, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_guides_check_order(NULL), LML_STATUS_INVALID_ARGUMENT);
    lml_guides_free(NULL);
}

/* Guides that cannot initialise a field: too few, out of order, from another mesh. */
static void bad_guides(const LmlMesh *mesh, const LmlEdgePoint *starts)
{
    LmlEdgePoint shuffled[3];
    LmlGuides *one = NULL, *misordered = NULL, *foreign = NULL;
    LmlMesh *small = NULL;
    Cylinder other;
    double field[1], target = 0.0;
    size_t needed = 0, crossings = 99;

    CHECK_STATUS(lml_guides_trace(mesh, starts, 1, THETA, 90.0, NULL, &one), LML_STATUS_OK);
    CHECK_STATUS(lml_guides_check_order(one), LML_STATUS_OK);
    CHECK_STATUS(lml_field_values_from_guides(mesh, one, field, 1, &needed, &target), LML_STATUS_INVALID_GUIDES);
    CHECK_MESSAGE("1 guide curve(s) given");
    CHECK_STATUS(lml_field_values_from_guides(NULL, one, field, 1, &needed, &target), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("mesh");
    CHECK_STATUS(lml_field_values_from_guides(mesh, NULL, field, 1, &needed, &target), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("guides");

    /* Curve 1 (the top one) does not lie between curves 0 and 2. */
    shuffled[0] = starts[0];
    shuffled[1] = starts[2];
    shuffled[2] = starts[1];
    CHECK_STATUS(lml_guides_trace(mesh, shuffled, 3, THETA, 90.0, NULL, &misordered), LML_STATUS_OK);
    CHECK_STATUS(lml_guides_crossings(misordered, NULL, 0, &crossings), LML_STATUS_OK);
    CHECK(crossings == 0);
    CHECK_STATUS(lml_guides_check_order(misordered), LML_STATUS_INVALID_GUIDES);
    CHECK_MESSAGE("guide curve 1 does not lie between guide curves 0 and 2");

    /* Guides traced on a coarser cylinder do not fit the harness mesh. */
    if (cylinder_generate(&other, 10, 6, 3)) {
        LmlEdgePoint p;
        double click[3] = {CYLINDER_RADIUS + 1.0, 0.0, 7.0};
        CHECK_STATUS(lml_mesh_new(other.xyz, other.vertex_count, other.triangles, other.triangle_count, &small), LML_STATUS_OK);
        CHECK_STATUS(lml_boundary_start_nearest(small, click, &p), LML_STATUS_OK);
        shuffled[0] = p;
        click[2] = 11.0;
        CHECK_STATUS(lml_boundary_start_nearest(small, click, &p), LML_STATUS_OK);
        shuffled[1] = p;
        CHECK_STATUS(lml_guides_trace(small, shuffled, 2, THETA, 90.0, NULL, &foreign), LML_STATUS_OK);
        lml_mesh_free(small);
        CHECK_STATUS(lml_field_values_from_guides(mesh, foreign, field, 1, &needed, &target), LML_STATUS_INVALID_ARGUMENT);
        CHECK_MESSAGE("were traced on a mesh with 77 vertices; `mesh` has");
        cylinder_free(&other);
    }
    lml_guides_free(foreign);
    lml_guides_free(misordered);
    lml_guides_free(one);
}

void test_guides(const Cylinder *c)
{
    LmlMesh *mesh = NULL;
    LmlGuides *guides = NULL;
    LmlEdgePoint starts[GUIDES];
    Polylines p;
    double *normals = mesh_normals(c);

    CHECK_STATUS(lml_mesh_new(c->xyz, c->vertex_count, c->triangles, c->triangle_count, &mesh), LML_STATUS_OK);
    if (mesh == NULL || normals == NULL) {
        CHECK(!"mesh and normals");
        lml_mesh_free(mesh);
        free(normals);
        return;
    }
    left_starts(mesh, c, starts);
    bad_inputs(mesh, c, starts);
    bad_guides(mesh, starts);
    check_crossings(mesh, c, normals);

    /* The parallel family: perpendicular to the left side (alpha = 90), the guides keep their
     * own copy of the mesh. */
    CHECK_STATUS(lml_guides_trace(mesh, starts, GUIDES, THETA, 90.0, NULL, &guides), LML_STATUS_OK);
    if (guides != NULL && read_guides(guides, &p)) {
        size_t crossings = 99;
        CHECK_STATUS(lml_guides_crossings(guides, NULL, 0, &crossings), LML_STATUS_OK);
        CHECK(crossings == 0);
        check_family(guides, c, normals, &p);
        check_guide_field(mesh, guides, c, &p);
        check_strokes(mesh, c, normals, &p);
        bad_strokes(mesh, &p);
        polylines_free(&p);
    } else {
        CHECK(!"traced and read");
    }
    lml_guides_free(guides);
    lml_mesh_free(mesh);
    free(normals);
}
