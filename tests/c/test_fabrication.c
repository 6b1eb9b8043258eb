#include "check.h"
#include "harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define THICKNESS 0.02
#define STOCK_LENGTH 8.0

static LmlFabrication *poisoned(void)
{
    static int marker;
    return (LmlFabrication *)(void *)&marker;
}

static void sub(const double *a, const double *b, double *out)
{
    out[0] = a[0] - b[0];
    out[1] = a[1] - b[1];
    out[2] = a[2] - b[2];
}

static double dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross(const double *a, const double *b, double *out)
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* Weak-axis curvature at p: the curvature vector of the circle through a, p, b (from the
 * circumcentre) along the unit normal (tangent x ruling) of the strip, the tangent along
 * next - previous. */
static double weak_axis_curvature(const double *a, const double *p, const double *b, const double *previous, const double *next,
                                  const double *ruling)
{
    double u[3], v[3], w[3], n[3], t[3], normal[3], centre[3];
    double uu, vv, area2, cc, k;
    int i;
    sub(a, p, u);
    sub(b, p, v);
    cross(u, v, n);
    area2 = dot(n, n);
    if (area2 == 0.0) {
        return 0.0;
    }
    uu = dot(u, u);
    vv = dot(v, v);
    for (i = 0; i < 3; i++) {
        w[i] = v[i] * uu - u[i] * vv;
    }
    cross(w, n, centre);
    for (i = 0; i < 3; i++) {
        centre[i] /= 2.0 * area2;
    }
    cc = dot(centre, centre);
    sub(next, previous, t);
    cross(t, ruling, normal);
    k = dot(centre, normal) / (cc * sqrt(dot(normal, normal)));
    return fabs(k);
}

static void bad_inputs(const LmlStrips *strips, const LmlMaterial *timber, const LmlStock *stock)
{
    LmlFabrication *fabrication = poisoned();
    LmlMaterial material;
    LmlStock short_stock = *stock;
    LmlMaterial soft = *timber;

    CHECK_STATUS(lml_material_preset("cheese", &material), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("cheese");
    CHECK_STATUS(lml_material_preset(NULL, &material), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_material_preset("steel", NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_stock_default(4.8, NULL), LML_STATUS_INVALID_ARGUMENT);

    CHECK_STATUS(lml_fabrication_new(strips, timber, -0.006, stock, &fabrication), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("thickness");
    CHECK(fabrication == NULL);
    CHECK_STATUS(lml_fabrication_new(strips, timber, NAN, stock, &fabrication), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("thickness");
    short_stock.length = 2.0 * stock->overlap;
    CHECK_STATUS(lml_fabrication_new(strips, timber, THICKNESS, &short_stock, &fabrication), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("stock_length");
    short_stock = *stock;
    short_stock.width = -1.0;
    CHECK_STATUS(lml_fabrication_new(strips, timber, THICKNESS, &short_stock, &fabrication), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("stock_width");
    soft.shear_modulus = 0.0;
    CHECK_STATUS(lml_fabrication_new(strips, &soft, THICKNESS, stock, &fabrication), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("shear_modulus");
    CHECK_STATUS(lml_fabrication_new(NULL, timber, THICKNESS, stock, &fabrication), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_fabrication_new(strips, NULL, THICKNESS, stock, &fabrication), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_fabrication_new(strips, timber, THICKNESS, NULL, &fabrication), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_fabrication_new(strips, timber, THICKNESS, stock, NULL), LML_STATUS_INVALID_ARGUMENT);
    lml_fabrication_free(NULL);
}

/* Two-call pattern on a text output; returns the malloc'd text or NULL. */
static char *text_of(const LmlFabrication *fabrication, uint32_t kind, size_t index)
{
    size_t needed = 0;
    char *text;
    CHECK_STATUS(lml_fabrication_text(fabrication, kind, index, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed > 1);
    text = malloc(needed);
    if (text == NULL) {
        return NULL;
    }
    CHECK_STATUS(lml_fabrication_text(fabrication, kind, index, (uint8_t *)text, needed - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_fabrication_text(fabrication, kind, index, (uint8_t *)text, needed, &needed), LML_STATUS_OK);
    CHECK(text[needed - 1] == '\0' && strlen(text) == needed - 1);
    return text;
}

static void check_plan(const LmlStrips *strips, const LmlFabrication *fabrication, const LmlStock *stock, const LmlMaterial *timber)
{
    LmlFabricationSummary summary;
    size_t s = 0, needed = 0, points = 0, i, j, k;
    LmlStripCheck *checks;
    LmlPiece *pieces;
    size_t *offsets;
    double *centres, *rulings;
    char *dxf, *id, *csv;

    CHECK_STATUS(lml_strips_count(strips, &s), LML_STATUS_OK);
    CHECK_STATUS(lml_fabrication_summary(fabrication, &summary), LML_STATUS_OK);
    CHECK(summary.strips == s && summary.pieces > s && summary.boards > 0);
    CHECK(summary.material_yield > 0.0 && summary.material_yield <= 1.0);
    CHECK(summary.board_size[0] == STOCK_LENGTH && summary.board_size[1] > 0.0);

    CHECK_STATUS(lml_fabrication_strip_checks(fabrication, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == s);
    checks = malloc(s * sizeof *checks + 1);
    offsets = malloc((s + 1) * sizeof *offsets);
    CHECK_STATUS(lml_strips_point_offsets(strips, offsets, s + 1, &needed), LML_STATUS_OK);
    points = offsets[s];
    centres = malloc(3 * points * sizeof *centres + 1);
    rulings = malloc(3 * points * sizeof *rulings + 1);
    CHECK_STATUS(lml_fabrication_strip_checks(fabrication, checks, s, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_strips_centres(strips, centres, 3 * points, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_strips_rulings(strips, rulings, 3 * points, &needed), LML_STATUS_OK);

    CHECK_STATUS(lml_fabrication_pieces(fabrication, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == summary.pieces);
    pieces = malloc(needed * sizeof *pieces + 1);
    CHECK_STATUS(lml_fabrication_pieces(fabrication, pieces, needed - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_fabrication_pieces(fabrication, pieces, needed, &needed), LML_STATUS_OK);

    for (i = 0; i < s; i++) {
        /* Independent strain: t/2 times the largest weak-axis curvature of the centre line, from the
         * circle through the points two apart (one apart next to the ends). */
        double most = 0.0, length = 0.0, covered = 0.0, expected;
        size_t count = 0;
        for (j = offsets[i] + 1; j + 1 < offsets[i + 1]; j++) {
            size_t reach = (j - offsets[i] >= 2 && offsets[i + 1] - 1 - j >= 2) ? 2 : 1;
            double kappa = weak_axis_curvature(&centres[3 * (j - reach)], &centres[3 * j], &centres[3 * (j + reach)], &centres[3 * (j - 1)],
                                               &centres[3 * (j + 1)], &rulings[3 * j]);
            most = kappa > most ? kappa : most;
        }
        for (j = offsets[i]; j + 1 < offsets[i + 1]; j++) {
            double e[3];
            sub(&centres[3 * (j + 1)], &centres[3 * j], e);
            length += sqrt(dot(e, e));
        }
        CHECK(fabs(checks[i].max_strain - 0.5 * THICKNESS * most) <= 1e-6 * checks[i].max_strain);
        CHECK(fabs(checks[i].max_bending_stress - timber->youngs_modulus * checks[i].max_strain) <= 1e-9 * checks[i].max_bending_stress);
        CHECK(checks[i].max_utilisation >= checks[i].max_bending_stress / timber->allowable_stress * (1.0 - 1e-12));
        CHECK(checks[i].overstressed == (checks[i].max_utilisation > 1.0));
        CHECK(checks[i].worst_point < offsets[i + 1] - offsets[i]);
        CHECK(checks[i].min_bending_radius > 0.0);
        /* The pieces of strip i cover it with one overlap per splice, each within the stock. */
        for (k = 0; k < summary.pieces; k++) {
            if (pieces[k].strip != i) {
                continue;
            }
            covered += pieces[k].length;
            count++;
            CHECK(pieces[k].number == count);
            CHECK(pieces[k].size[0] <= STOCK_LENGTH && pieces[k].board >= 1 && pieces[k].board <= summary.boards);
            CHECK(pieces[k].previous == (count == 1 ? -1 : (int64_t)k - 1));
            CHECK(pieces[k].max_utilisation <= checks[i].max_utilisation + 1e-12);
        }
        expected = length + stock->overlap * (double)(count - 1);
        CHECK(count >= 1 && fabs(covered - expected) <= 1e-9 * expected);
    }

    dxf = text_of(fabrication, LML_FABRICATION_TEXT_CUT_DXF, 0);
    if (dxf != NULL) {
        CHECK(strstr(dxf, "AC1009") != NULL);
        CHECK(occurrences(dxf, "POLYLINE\n  8\nOUTLINE\n") == summary.pieces);
        CHECK(occurrences(dxf, "POLYLINE\n  8\nCENTRELINE\n") == summary.pieces);
        CHECK(occurrences(dxf, "TEXT\n  8\nLABEL\n") == summary.pieces);
        CHECK(strstr(dxf, "\n  0\nEOF\n") != NULL);
    }
    id = text_of(fabrication, LML_FABRICATION_TEXT_PIECE_ID, 1);
    if (id != NULL) {
        char expected_id[64];
        snprintf(expected_id, sizeof expected_id, "strip_%u-%u", (unsigned)pieces[1].strip, (unsigned)pieces[1].number);
        CHECK(strcmp(id, expected_id) == 0);
    }
    csv = text_of(fabrication, LML_FABRICATION_TEXT_BOM_CSV, 0);
    if (csv != NULL) {
        CHECK(occurrences(csv, "\n") == summary.pieces + 1);
        /* The strips were built for θ = 60°: every row names their family and θ. */
        CHECK(occurrences(csv, ",pseudo-geodesic,60.000000,") == summary.pieces);
    }
    CHECK_STATUS(lml_fabrication_text(fabrication, LML_FABRICATION_TEXT_PIECE_ID, summary.pieces, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("index");
    CHECK_STATUS(lml_fabrication_text(fabrication, 9, 0, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("kind");
    CHECK_STATUS(lml_fabrication_pieces(NULL, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_fabrication_strip_checks(fabrication, NULL, 0, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_fabrication_summary(fabrication, NULL), LML_STATUS_INVALID_ARGUMENT);
    free(dxf);
    free(id);
    free(csv);
    free(checks);
    free(pieces);
    free(offsets);
    free(centres);
    free(rulings);
}

void test_fabrication(const LmlCurves *curves)
{
    LmlStripParams params;
    LmlStrips *strips = NULL;
    LmlFabrication *fabrication = NULL;
    LmlMaterial timber, steel;
    LmlStock stock;

    CHECK(curves != NULL);
    if (curves == NULL) {
        return;
    }
    CHECK_STATUS(lml_strip_params_default(60.0, 1.0, &params), LML_STATUS_OK);
    CHECK_STATUS(lml_strips_new(curves, &params, &strips), LML_STATUS_OK);
    CHECK_STATUS(lml_material_preset("timber", &timber), LML_STATUS_OK);
    CHECK(timber.youngs_modulus == 11e9 && timber.shear_modulus == 0.69e9 && timber.allowable_stress == 24e6);
    CHECK_STATUS(lml_material_preset("steel", &steel), LML_STATUS_OK);
    CHECK(steel.youngs_modulus == 210e9);
    CHECK_STATUS(lml_stock_default(STOCK_LENGTH, &stock), LML_STATUS_OK);
    CHECK(stock.length == STOCK_LENGTH && stock.width == 0.0 && stock.overlap == 0.3 && stock.gap == 0.01);
    if (strips == NULL) {
        return;
    }
    bad_inputs(strips, &timber, &stock);
    CHECK_STATUS(lml_fabrication_new(strips, &timber, THICKNESS, &stock, &fabrication), LML_STATUS_OK);
    if (fabrication != NULL) {
        check_plan(strips, fabrication, &stock, &timber);
    }
    lml_fabrication_free(fabrication);
    lml_strips_free(strips);
}
