#include "check.h"
#include "harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The page with the two-call pattern (checking the too-small calls), or NULL. */
static char *page(const LmlStrips *strips, const LmlCurves *curves, const double *utilisation, size_t count, const char *title)
{
    size_t needed = 0;
    char *text;
    CHECK_STATUS(lml_strips_view_html(strips, curves, utilisation, count, title, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed > 1);
    text = malloc(needed);
    if (text == NULL) {
        return NULL;
    }
    CHECK_STATUS(lml_strips_view_html(strips, curves, utilisation, count, title, (uint8_t *)text, needed - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_strips_view_html(strips, curves, utilisation, count, title, (uint8_t *)text, needed, &needed), LML_STATUS_OK);
    CHECK(text[needed - 1] == '\0' && strlen(text) == needed - 1);
    return text;
}

/* Every vertex of the strips inside the bounding box the page embeds. */
static void check_box(const LmlStrips *strips, const char *text)
{
    double low[3], high[3], *xyz;
    size_t needed = 0, i;
    int k, inside = 1;
    const char *box = strstr(text, "\"box\":{\"high\":[");
    CHECK(box != NULL);
    if (box == NULL) {
        return;
    }
    CHECK(sscanf(box, "\"box\":{\"high\":[%lf,%lf,%lf],\"low\":[%lf,%lf,%lf]}", &high[0], &high[1], &high[2], &low[0], &low[1], &low[2]) == 6);
    CHECK_STATUS(lml_strips_vertices(strips, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    xyz = malloc(needed * sizeof *xyz + 1);
    if (xyz == NULL) {
        return;
    }
    CHECK_STATUS(lml_strips_vertices(strips, xyz, needed, &needed), LML_STATUS_OK);
    for (i = 0; i < needed; i++) {
        k = (int)(i % 3);
        inside = inside && xyz[i] >= low[k] && xyz[i] <= high[k];
    }
    CHECK(needed > 0 && inside);
    free(xyz);
}

void test_view(const LmlCurves *curves)
{
    LmlStripParams params;
    LmlStrips *strips = NULL;
    size_t s = 0, i, needed = 0;
    double *utilisation;
    char *full, *again, *alone, *stressed;
    char name[32];

    CHECK(curves != NULL);
    if (curves == NULL) {
        return;
    }
    CHECK_STATUS(lml_strip_params_default(60.0, 1.0, &params), LML_STATUS_OK);
    CHECK_STATUS(lml_strips_new(curves, &params, &strips), LML_STATUS_OK);
    if (strips == NULL) {
        return;
    }
    CHECK_STATUS(lml_strips_count(strips, &s), LML_STATUS_OK);
    CHECK(s > 0);

    full = page(strips, curves, NULL, 0, "cylinder <test>");
    again = page(strips, curves, NULL, 0, "cylinder <test>");
    alone = page(strips, NULL, NULL, 0, NULL);
    utilisation = malloc(s * sizeof *utilisation);
    stressed = NULL;
    if (utilisation != NULL) {
        for (i = 0; i < s; i++) {
            utilisation[i] = 0.25 * (double)(i + 1);
        }
        stressed = page(strips, curves, utilisation, s, "cylinder");
    }
    if (full != NULL && again != NULL && alone != NULL && stressed != NULL) {
        /* One self-contained page, nothing loaded from elsewhere, the title escaped. */
        CHECK(strncmp(full, "<!DOCTYPE html>", 15) == 0);
        CHECK(strstr(full, "http://") == NULL && strstr(full, "https://") == NULL && strstr(full, "src=") == NULL);
        CHECK(strstr(full, "<title>cylinder &lt;test&gt; · Lamella</title>") != NULL);
        CHECK(occurrences(full, "</script>") == 2);
        /* Every strip, named strip_<i>, with its Table 4 figures; the surface and curves. */
        for (i = 0; i < s; i++) {
            sprintf(name, "\"name\":\"strip_%u\"", (unsigned)i);
            CHECK(occurrences(full, name) == 1);
        }
        CHECK(occurrences(full, "\"max_diff_theta_degrees\":") == s);
        CHECK(strstr(full, "\"surface\":{") != NULL && strstr(alone, "\"surface\":null") != NULL);
        CHECK(strstr(full, "\"has_utilisation\":false") != NULL && strstr(stressed, "\"has_utilisation\":true") != NULL);
        CHECK(strstr(stressed, "\"utilisation\":0.25") != NULL);
        CHECK(strstr(alone, "<title>Lamella strips · Lamella</title>") != NULL);
        /* Deterministic: the same inputs give the same bytes. */
        CHECK(strcmp(full, again) == 0);
        check_box(strips, full);
    }

    /* Every invalid input. */
    CHECK_STATUS(lml_strips_view_html(NULL, curves, NULL, 0, NULL, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("strips");
    CHECK_STATUS(lml_strips_view_html(strips, curves, NULL, 0, NULL, NULL, 0, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("needed");
    if (utilisation != NULL) {
        CHECK_STATUS(lml_strips_view_html(strips, curves, utilisation, s + 1, NULL, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
        CHECK_MESSAGE("utilisation_count");
        utilisation[s - 1] = NAN;
        CHECK_STATUS(lml_strips_view_html(strips, curves, utilisation, s, NULL, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
        CHECK_MESSAGE("utilisation NaN is not finite");
    }
    CHECK_STATUS(lml_strips_view_html(strips, curves, NULL, 0, "\xff\xfe", NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("title");
    free(full);
    free(again);
    free(alone);
    free(stressed);
    free(utilisation);
    lml_strips_free(strips);
}
