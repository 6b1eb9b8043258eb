/* The hyperbolic paraboloid of the 3-web tests and the arrays of a strip web (see hypar.h). */
#include "hypar.h"

#include "check.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A deterministic displacement in [-0.25, 0.25] cells. */
static double jitter(size_t v, int k)
{
    double x = sin(12.9898 * (double)v + 78.233 * (double)k) * 43758.5453;
    return 0.5 * (x - floor(x)) - 0.25;
}

double distance(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

void hypar_generate(Hypar *h)
{
    const double cell = 2.0 * HALF_WIDTH / CELLS;
    size_t i, j, edges = 0;
    double total = 0.0;
    h->n = GRID_VERTICES;
    h->m = 2 * CELLS * CELLS;
    for (j = 0; j <= CELLS; j++) {
        for (i = 0; i <= CELLS; i++) {
            size_t v = j * (CELLS + 1) + i;
            double x = -HALF_WIDTH + cell * ((double)i + ((i > 0 && i < CELLS) ? jitter(v, 0) : 0.0));
            double y = -HALF_WIDTH + cell * ((double)j + ((j > 0 && j < CELLS) ? jitter(v, 1) : 0.0));
            h->xyz[3 * v] = x;
            h->xyz[3 * v + 1] = y;
            h->xyz[3 * v + 2] = x * y / HYPAR_C;
        }
    }
    for (j = 0; j < CELLS; j++) {
        for (i = 0; i < CELLS; i++) {
            uint32_t a = (uint32_t)(j * (CELLS + 1) + i), b = a + 1, d = a + CELLS + 1, e = d + 1;
            uint32_t *t = h->triangles + 6 * (j * CELLS + i);
            /* Counter-clockwise seen from above: normals point up. */
            if ((i + j) % 2 == 0) {
                t[0] = a; t[1] = b; t[2] = e; t[3] = a; t[4] = e; t[5] = d;
                total += distance(h->xyz + 3 * a, h->xyz + 3 * e);
            } else {
                t[0] = a; t[1] = b; t[2] = d; t[3] = b; t[4] = e; t[5] = d;
                total += distance(h->xyz + 3 * b, h->xyz + 3 * d);
            }
            edges++;
        }
    }
    /* The grid's rows and columns of edges. */
    for (j = 0; j <= CELLS; j++) {
        for (i = 0; i < CELLS; i++) {
            total += distance(h->xyz + 3 * (j * (CELLS + 1) + i), h->xyz + 3 * (j * (CELLS + 1) + i + 1));
            total += distance(h->xyz + 3 * (i * (CELLS + 1) + j), h->xyz + 3 * ((i + 1) * (CELLS + 1) + j));
            edges += 2;
        }
    }
    h->mean_edge = total / (double)edges;
}

void hypar_normal(const double *p, double *n)
{
    double gx = -p[1] / HYPAR_C, gy = -p[0] / HYPAR_C, length = sqrt(gx * gx + gy * gy + 1.0);
    n[0] = gx / length;
    n[1] = gy / length;
    n[2] = 1.0 / length;
}

double hypar_distance(const double *p)
{
    return fabs(p[2] - p[0] * p[1] / HYPAR_C) / sqrt(1.0 + (p[0] * p[0] + p[1] * p[1]) / (HYPAR_C * HYPAR_C));
}

void *allocate(size_t count, size_t size)
{
    void *p = malloc(count * size + 1);
    if (p == NULL) {
        CHECK(!"out of memory");
    }
    return p;
}

void free_web_arrays(WebArrays *a)
{
    int k;
    free(a->xyz);
    free(a->levels);
    free(a->face_sizes);
    free(a->faces);
    free(a->nodes);
    for (k = 0; k < 3; k++) {
        free(a->polyline_sizes[k]);
        free(a->polyline_vertices[k]);
        free(a->polyline_levels[k]);
    }
    memset(a, 0, sizeof *a);
}

int read_web(const LmlStripWeb *web, WebArrays *a)
{
    size_t needed = 0;
    uint32_t k;
    memset(a, 0, sizeof *a);
    CHECK_STATUS(lml_strip_web_vertices(web, NULL, 0, &a->vertex_count), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_strip_web_face_sizes(web, NULL, 0, &a->face_count), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_strip_web_face_vertices(web, NULL, 0, &a->face_index_count), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_strip_web_nodes(web, NULL, 0, &a->node_count), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(a->vertex_count % 3 == 0);
    a->vertex_count /= 3;
    a->xyz = allocate(3 * a->vertex_count, sizeof(double));
    a->levels = allocate(3 * a->vertex_count, sizeof(int64_t));
    a->face_sizes = allocate(a->face_count, sizeof(uint32_t));
    a->faces = allocate(a->face_index_count, sizeof(uint32_t));
    a->nodes = allocate(a->node_count, sizeof(LmlWebNode));
    if (a->xyz == NULL || a->levels == NULL || a->face_sizes == NULL || a->faces == NULL || a->nodes == NULL) {
        return 0;
    }
    CHECK_STATUS(lml_strip_web_vertices(web, a->xyz, 3 * a->vertex_count, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_strip_web_vertex_levels(web, a->levels, 3 * a->vertex_count - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == 3 * a->vertex_count);
    CHECK_STATUS(lml_strip_web_vertex_levels(web, a->levels, 3 * a->vertex_count, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_strip_web_face_sizes(web, a->face_sizes, a->face_count, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_strip_web_face_vertices(web, a->faces, a->face_index_count, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_strip_web_nodes(web, a->nodes, a->node_count, &needed), LML_STATUS_OK);
    for (k = 0; k < 3; k++) {
        size_t count = 0;
        CHECK_STATUS(lml_strip_web_polyline_sizes(web, k, NULL, 0, &a->polyline_count[k]), LML_STATUS_BUFFER_TOO_SMALL);
        CHECK_STATUS(lml_strip_web_polyline_vertices(web, k, NULL, 0, &a->polyline_index_count[k]), LML_STATUS_BUFFER_TOO_SMALL);
        a->polyline_sizes[k] = allocate(a->polyline_count[k], sizeof(uint32_t));
        a->polyline_levels[k] = allocate(a->polyline_count[k], sizeof(uint32_t));
        a->polyline_vertices[k] = allocate(a->polyline_index_count[k], sizeof(uint32_t));
        if (a->polyline_sizes[k] == NULL || a->polyline_levels[k] == NULL || a->polyline_vertices[k] == NULL) {
            return 0;
        }
        CHECK_STATUS(lml_strip_web_polyline_sizes(web, k, a->polyline_sizes[k], a->polyline_count[k], &needed), LML_STATUS_OK);
        CHECK_STATUS(lml_strip_web_polyline_levels(web, k, a->polyline_levels[k], a->polyline_count[k], &count), LML_STATUS_OK);
        CHECK(count == a->polyline_count[k]);
        CHECK_STATUS(lml_strip_web_polyline_vertices(web, k, a->polyline_vertices[k], a->polyline_index_count[k], &needed), LML_STATUS_OK);
    }
    return 1;
}
