#include "vault.h"

#include <stdlib.h>

#define HALF_SPAN 6.0
#define RISE 4.0
#define LENGTH 12.0

int vault_generate(Vault *v, unsigned cells)
{
    unsigned i, j;
    v->vertex_count = (size_t)(cells + 1) * (cells + 1);
    v->triangle_count = (size_t)2 * cells * cells;
    v->xyz = malloc(3 * v->vertex_count * sizeof(double));
    v->triangles = malloc(3 * v->triangle_count * sizeof(uint32_t));
    if (v->xyz == NULL || v->triangles == NULL) {
        vault_free(v);
        return 0;
    }
    for (j = 0; j <= cells; j++) {
        for (i = 0; i <= cells; i++) {
            double *p = v->xyz + 3 * ((size_t)j * (cells + 1) + i);
            double x = -HALF_SPAN + 2.0 * HALF_SPAN * i / cells;
            p[0] = x;
            p[1] = LENGTH * j / cells;
            p[2] = RISE * (1.0 - (x / HALF_SPAN) * (x / HALF_SPAN));
        }
    }
    for (j = 0; j < cells; j++) {
        for (i = 0; i < cells; i++) {
            uint32_t a = j * (cells + 1) + i, b = a + 1, d = a + cells + 1, e = d + 1;
            uint32_t *t = v->triangles + 6 * ((size_t)j * cells + i);
            /* Counter-clockwise seen from above: normals point up. */
            t[0] = a; t[1] = b; t[2] = e;
            t[3] = a; t[4] = e; t[5] = d;
        }
    }
    return 1;
}

void vault_free(Vault *v)
{
    free(v->xyz);
    free(v->triangles);
    v->xyz = NULL;
    v->triangles = NULL;
}
