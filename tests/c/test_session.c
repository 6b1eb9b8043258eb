#include "check.h"
#include "harness.h"

#include <stdlib.h>
#include <string.h>

/* Saves `field` with the two-call pattern; returns a malloc'd buffer and its size, or NULL. */
static uint8_t *save(const LmlField *field, size_t *size)
{
    uint8_t *bytes;
    *size = 0;
    CHECK_STATUS(lml_field_save(field, NULL, 0, size), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(*size > 8);
    bytes = malloc(*size);
    if (bytes == NULL) {
        return NULL;
    }
    CHECK_STATUS(lml_field_save(field, bytes, *size - 1, size), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_field_save(field, bytes, *size, size), LML_STATUS_OK);
    return bytes;
}

/* Expects loading `length` bytes to fail with LML_STATUS_CORRUPT_DATA naming `part`. */
static void expect_corrupt(const uint8_t *bytes, size_t length, const char *part, int line)
{
    LmlField *field = NULL;
    check_status(lml_field_load(bytes, length, &field), LML_STATUS_CORRUPT_DATA, __FILE__, line, "lml_field_load");
    check(field == NULL, __FILE__, line, "out reset to NULL");
    check_message(part, __FILE__, line);
    lml_field_free(field);
}

/* Two reports are identical, field by field (the struct may contain padding). */
static int same_report(const LmlReport *a, const LmlReport *b)
{
    return a->iterations == b->iterations && a->iterations_this_step == b->iterations_this_step &&
           a->stage == b->stage && a->energy_fair == b->energy_fair && a->energy_grad == b->energy_grad &&
           a->energy_angle == b->energy_angle && a->energy_frame == b->energy_frame &&
           a->energy_total == b->energy_total && a->angle_error_rms_degrees == b->angle_error_rms_degrees &&
           a->angle_error_max_degrees == b->angle_error_max_degrees && a->measured_vertices == b->measured_vertices &&
           a->singular_vertex_count == b->singular_vertex_count && a->flips == b->flips && a->damping == b->damping &&
           a->converged == b->converged;
}

/* Two sessions hold bit-identical fields. */
static int same_fields(const LmlField *a, const LmlField *b, size_t n)
{
    double *fa = malloc(n * sizeof(double)), *fb = malloc(n * sizeof(double));
    size_t needed;
    int same = fa != NULL && fb != NULL && lml_field_values(a, fa, n, &needed) == LML_STATUS_OK &&
               lml_field_values(b, fb, n, &needed) == LML_STATUS_OK && memcmp(fa, fb, n * sizeof(double)) == 0;
    free(fa);
    free(fb);
    return same;
}

void test_session(LmlField *original)
{
    size_t size = 0, again_size = 0, n = 0, i;
    uint8_t *bytes = save(original, &size), *again = NULL, *damaged = NULL;
    LmlField *restored = NULL;
    LmlReport a, b;
    LmlWeights weights = {1e-3, 1e-4, 10.0};
    uint32_t version;
    LmlStatus status;

    if (bytes == NULL) {
        CHECK(!"out of memory");
        return;
    }
    CHECK(memcmp(bytes, "LMLF", 4) == 0);
    CHECK_STATUS(lml_field_values(original, NULL, 0, &n), LML_STATUS_BUFFER_TOO_SMALL);

    /* Round trip: load -> save gives the same bytes, the same field and the same report. */
    CHECK_STATUS(lml_field_load(bytes, size, &restored), LML_STATUS_OK);
    again = save(restored, &again_size);
    CHECK(again != NULL && again_size == size && memcmp(again, bytes, size) == 0);
    CHECK(same_fields(original, restored, n));
    CHECK_STATUS(lml_field_report(original, &a), LML_STATUS_OK);
    CHECK_STATUS(lml_field_report(restored, &b), LML_STATUS_OK);
    CHECK(same_report(&a, &b));

    /* Both continue identically after a change of weights (a converged session runs again). */
    CHECK_STATUS(lml_field_set_weights(original, weights), LML_STATUS_OK);
    CHECK_STATUS(lml_field_set_weights(restored, weights), LML_STATUS_OK);
    status = lml_field_step(original, 2, &a);
    CHECK(status == LML_STATUS_MORE || status == LML_STATUS_CONVERGED);
    CHECK(lml_field_step(restored, 2, &b) == status);
    CHECK(a.iterations_this_step >= 1 && same_report(&a, &b));
    CHECK(same_fields(original, restored, n));
    lml_field_free(restored);

    /* Truncated, damaged and foreign data. */
    expect_corrupt(bytes, 0, "magic", __LINE__);
    expect_corrupt(bytes, 7, "magic", __LINE__);
    expect_corrupt(bytes, 8, "session data", __LINE__);
    expect_corrupt(bytes, size / 2, "session data", __LINE__);
    expect_corrupt(bytes, size - 1, "session data", __LINE__);
    damaged = malloc(size + 1);
    if (damaged != NULL) {
        memcpy(damaged, bytes, size);
        damaged[size] = 0;
        expect_corrupt(damaged, size + 1, "session data", __LINE__);
        damaged[0] = 'X';
        expect_corrupt(damaged, size, "magic", __LINE__);
        memcpy(damaged, bytes, size);
        version = (uint32_t)damaged[4] | (uint32_t)damaged[5] << 8 | (uint32_t)damaged[6] << 16 | (uint32_t)damaged[7] << 24;
        version += 1;
        for (i = 0; i < 4; i++) {
            damaged[4 + i] = (uint8_t)(version >> (8 * i));
        }
        expect_corrupt(damaged, size, "version", __LINE__);
        /* A length field deep inside claims far more elements than there are bytes. */
        memcpy(damaged, bytes, size);
        for (i = 8; i < 16; i++) {
            damaged[i] = 0xFF;
        }
        expect_corrupt(damaged, size, "session data", __LINE__);
        free(damaged);
    }
    CHECK_STATUS(lml_field_load(NULL, 5, &restored), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("bytes");
    CHECK_STATUS(lml_field_load(bytes, size, NULL), LML_STATUS_INVALID_ARGUMENT);
    free(again);
    free(bytes);
}
