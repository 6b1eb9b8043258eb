/* The thread rules of the header: a handle may move between threads (one at a time),
 * different handles are independent, and the error message is per thread. */
#define _POSIX_C_SOURCE 200809L

#include "check.h"
#include "harness.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    LmlField *field;
    LmlStatus status;
    LmlReport report;
    int message_empty;
} Job;

/* Steps the job's field three iterations on whatever thread runs it. */
static void *step_three(void *arg)
{
    Job *job = arg;
    job->status = lml_field_step(job->field, 3, &job->report);
    job->message_empty = lml_last_error_message()[0] == '\0';
    return NULL;
}

static int run_threads(Job *jobs, int count)
{
    pthread_t threads[2];
    int i, started = 0;
    for (i = 0; i < count; i++) {
        started += pthread_create(&threads[i], NULL, step_three, &jobs[i]) == 0;
    }
    for (i = 0; i < started; i++) {
        pthread_join(threads[i], NULL);
    }
    return started == count;
}

/* The fields of two sessions are bit-identical. */
static int same_values(const LmlField *a, const LmlField *b, size_t n)
{
    double *va = malloc(n * sizeof(double)), *vb = malloc(n * sizeof(double));
    size_t needed;
    int same = va != NULL && vb != NULL && lml_field_values(a, va, n, &needed) == LML_STATUS_OK &&
               lml_field_values(b, vb, n, &needed) == LML_STATUS_OK && memcmp(va, vb, n * sizeof(double)) == 0;
    free(va);
    free(vb);
    return same;
}

void test_threads(const Cylinder *c)
{
    LmlMesh *mesh = NULL;
    LmlFieldParams params;
    LmlReport report;
    Job jobs[2];
    int i;

    memset(jobs, 0, sizeof jobs);
    CHECK_STATUS(lml_mesh_new(c->xyz, c->vertex_count, c->triangles, c->triangle_count, &mesh), LML_STATUS_OK);
    CHECK_STATUS(lml_field_params_default(LML_FAMILY_PSEUDO_GEODESIC, 60.0, &params), LML_STATUS_OK);
    for (i = 0; i < 2; i++) {
        CHECK_STATUS(lml_field_new(mesh, c->field, c->vertex_count, &params, &jobs[i].field), LML_STATUS_OK);
    }
    lml_mesh_free(mesh);
    if (jobs[0].field == NULL || jobs[1].field == NULL) {
        lml_field_free(jobs[0].field);
        lml_field_free(jobs[1].field);
        return;
    }

    /* A handle moves to another thread and back. The main thread's message survives. */
    CHECK_STATUS(lml_field_step(NULL, 1, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK(run_threads(jobs, 1));
    CHECK_STATUS(jobs[0].status, LML_STATUS_MORE);
    CHECK(jobs[0].message_empty);
    CHECK_MESSAGE("field");
    CHECK_STATUS(lml_field_step(jobs[0].field, 3, &report), LML_STATUS_MORE);
    CHECK(report.iterations == 6);

    /* Two handles stepped at the same time from two threads: independent and deterministic. */
    for (i = 0; i < 2; i++) {
        CHECK_STATUS(lml_field_step(jobs[1].field, 3, &report), LML_STATUS_MORE);
    }
    CHECK(run_threads(jobs, 2));
    CHECK_STATUS(jobs[0].status, LML_STATUS_MORE);
    CHECK_STATUS(jobs[1].status, LML_STATUS_MORE);
    CHECK(jobs[0].report.iterations == 9 && jobs[1].report.iterations == 9);
    CHECK(jobs[0].report.energy_total == jobs[1].report.energy_total);
    CHECK(same_values(jobs[0].field, jobs[1].field, c->vertex_count));

    lml_field_free(jobs[0].field);
    lml_field_free(jobs[1].field);
}
