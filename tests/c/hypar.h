/* The 3-web tests' surface, the hyperbolic paraboloid z = xy/5 over a jittered grid, with its
 * exact normal, and the arrays of an LmlStripWeb read with the two-call pattern (shared by the
 * 3-web test and the base-mesh optimisation of its web). */
#ifndef LAMELLA_HYPAR_H
#define LAMELLA_HYPAR_H

#include "lamella.h"

#include <stddef.h>
#include <stdint.h>

/* 19 x 19 jittered cells on [-5, 5]^2: 400 vertices (small enough for valgrind). */
#define CELLS 19
#define HALF_WIDTH 5.0
#define HYPAR_C 5.0
#define GRID_VERTICES ((CELLS + 1) * (CELLS + 1))

typedef struct {
    size_t n, m;
    double xyz[3 * GRID_VERTICES];
    uint32_t triangles[6 * CELLS * CELLS];
    /* The mean length of the mesh's edges, each counted once. */
    double mean_edge;
} Hypar;

/* The arrays of an LmlStripWeb. */
typedef struct {
    size_t vertex_count, face_count, face_index_count, node_count;
    double *xyz;
    int64_t *levels;
    uint32_t *face_sizes, *faces;
    LmlWebNode *nodes;
    size_t polyline_count[3], polyline_index_count[3];
    uint32_t *polyline_sizes[3], *polyline_vertices[3], *polyline_levels[3];
} WebArrays;

/* z = xy/5 over a jittered grid, the boundary straight, the diagonals alternating. */
void hypar_generate(Hypar *h);

/* The exact unit normal of z = xy/5 at (the plan position of) `p`, pointing up. */
void hypar_normal(const double *p, double *n);

/* The distance of `p` from z = xy/5, to first order: |z - xy/5| / |grad|. */
double hypar_distance(const double *p);

double distance(const double *a, const double *b);

/* `count` elements of `size` bytes (at least one byte, so that NULL means out of memory); a
 * failed check when there is none. */
void *allocate(size_t count, size_t size);

/* Reads every array of `web` with the two-call pattern; whether all were read. */
int read_web(const LmlStripWeb *web, WebArrays *a);

void free_web_arrays(WebArrays *a);

#endif
