/*
 * The C interface of polyguard, tested from C (crates/ffi/tests/run_c_tests.sh builds
 * and runs it against the static and the shared library).
 *
 * 1. The seven cases of examples/cases.jsonl, embedded below: each answer is checked
 *    against the truth worked out by hand in its comment (does the point enter, and at
 *    what time), and the method against paper A's dispatch rule (section II.F, III).
 *    With --cli FILE (the output of `polyguard detect --time examples/cases.jsonl`),
 *    every field is also compared with the command-line tool's line, floats bit for bit.
 * 2. Bad input: status codes, the message naming the field, the conservative answer
 *    written on an error, message truncation.
 * 3. pg_detect_batch against pg_detect on every pair, the capacity protocol, errors
 *    naming the element.
 * 4. pg_intervals and pg_detect_exit on cases worked out by hand (a square crossed, and
 *    the two cases of examples/intervals.jsonl: a cell entered twice, a drone leaving its
 *    keep-in box through the ceiling), the buffer protocol, errors naming the field.
 * 5. pg_encounters on the repository's three real flights (CSV of fixes) against two
 *    drifting cells (MF-JSON): the JSON Lines, their count, and with --encounters-cli
 *    FILE (the output of `polyguard encounters` on the same files and options) the text
 *    byte for byte; NULL texts, bad UTF-8, unreadable input, bad options and rejected
 *    rows as statuses.
 * 6. The way out: pg_course_bands checked course by course with pg_intervals (a course
 *    inside a clear band has no span of near_D, one inside a conflict band a certain
 *    span), the buffer protocol with a too-small buffer, speed bands; pg_recovery's
 *    point at distance >= D by a plain distance in C, an impossible keep-in; pg_offset's
 *    ring containing points at distance D and its vertices within D(1 + eps), the
 *    capacity protocol, and pg_inset's empty answer.
 *
 * Exit status 0 when every check passes; each failure is printed.
 */
#include "polyguard.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* pi, spelled out: M_PI is not C99 */
#define M_PI_VALUE 3.14159265358979323846

static int failures = 0;
static int checks = 0;

#define CHECK(cond, ...)                                                   \
    do {                                                                   \
        checks++;                                                          \
        if (!(cond)) {                                                     \
            failures++;                                                    \
            fprintf(stderr, "FAIL %s:%d: %s: ", __FILE__, __LINE__, #cond); \
            fprintf(stderr, __VA_ARGS__);                                  \
            fprintf(stderr, "\n");                                         \
        }                                                                  \
    } while (0)

static const char *last_message(void) {
    static char buf[512];
    int rc = pg_last_error_message(buf, sizeof buf);
    CHECK(rc == PG_OK, "pg_last_error_message: %s", pg_status_name(rc));
    return buf;
}

static int starts_with(const char *s, const char *prefix) {
    return strncmp(s, prefix, strlen(prefix)) == 0;
}

/* ---- 1. the example cases ---------------------------------------------------- */

static const pg_vec2 SQUARE[4] = {{0.0, 0.0}, {2.0, 0.0}, {2.0, 2.0}, {0.0, 2.0}};
static const pg_vec2 EAST[4] = {{1.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}};
static const pg_vec2 TRIANGLE[3] = {{0.0, 0.0}, {2.0, 0.0}, {1.0, 2.0}};
static const pg_vec2 BIG[4] = {{0.0, 0.0}, {10.0, 0.0}, {10.0, 10.0}, {0.0, 10.0}};
static const pg_vec2 GROW[4] = {{-0.1, -0.05}, {0.1, -0.05}, {0.1, 0.05}, {-0.1, 0.05}};

struct example {
    const char *id;
    double lookahead, buff, fac;
    pg_point point;
    pg_polygon polygon;
    /* the truth, by hand: does the point enter the closed polygon (and slab), when */
    int enters;
    double entry;
    int method;
};

#define P2(x, y, vx, vy) {{x, y}, {vx, vy}, 0, 0.0, 0.0}
#define P3(x, y, z, vx, vy, vz) {{x, y}, {vx, vy}, 1, z, vz}
#define POLY(v, vel, n) {v, vel, n, 0, {0.0, 0.0, 0.0}}
#define POLY3(v, vel, n, b, t, vz) {v, vel, n, 1, {b, t, vz}}

static const struct example EXAMPLES[] = {
    /* The square's x-range is [t, 2 + t], the point's x is 5: inside for t in [3, 5];
       its y = -3 + t reaches 0 at t = 3. First contact at the corner (5, 0), t = 3. */
    {"static-hit", 10.0, 0.01, 0.0001, P2(5.0, -3.0, 0.0, 1.0), POLY(SQUARE, EAST, 4), 1, 3.0,
     PG_METHOD_SAME_2D},
    /* The same until T = 2.5: y <= -0.5 while the square keeps y >= 0, 50 BUFFs away. */
    {"static-miss", 2.5, 0.01, 0.0001, P2(5.0, -3.0, 0.0, 1.0), POLY(SQUARE, EAST, 4), 0, 0.0,
     PG_METHOD_SAME_2D},
    /* (1, 1) is inside the resting triangle from the start. */
    {"at-rest-inside", 1.0, 0.01, 0.0001, P2(1.0, 1.0, 0.0, 0.0), POLY(TRIANGLE, NULL, 3), 1, 0.0,
     PG_METHOD_SAME_2D},
    /* The left edge is x = -0.1 t for y in [-0.05 t, 10 + 0.05 t], which holds y = 5;
       the point's x = -50 + 0.5 t meets it when 0.6 t = 50: t = 83.33... */
    {"warping-hit", 300.0, 0.01, 0.0001, P2(-50.0, 5.0, 0.5, 0.0), POLY(BIG, GROW, 4), 1,
     50.0 / 0.6, PG_METHOD_DIFF_2D},
    /* y = 50 while the top edge stays below 10 + 0.05 * 300 = 25. */
    {"warping-miss", 300.0, 0.01, 0.0001, P2(-50.0, 50.0, 0.5, 0.0), POLY(BIG, GROW, 4), 0, 0.0,
     PG_METHOD_DIFF_2D},
    /* x = -3 + t is in [0, 2] for t in [3, 5]; z = 20 - 2 t reaches the top 10 at t = 5,
       when the point is on the right edge: a touch at t = 5 (tangent in time). */
    {"3d-descends-in", 10.0, 0.01, 0.0001, P3(-3.0, 1.0, 20.0, 1.0, 0.0, -2.0),
     POLY3(SQUARE, NULL, 4, 0.0, 10.0, 0.0), 1, 5.0, PG_METHOD_3D},
    /* z = 20 - t is 15 to 17 while x is in [0, 2]: 5 above the top. */
    {"3d-passes-over", 10.0, 0.01, 0.0001, P3(-3.0, 1.0, 20.0, 1.0, 0.0, -1.0),
     POLY3(SQUARE, NULL, 4, 0.0, 10.0, 0.0), 0, 0.0, PG_METHOD_3D},
};
#define N_EXAMPLES (sizeof EXAMPLES / sizeof EXAMPLES[0])

static pg_params params_for(double lookahead, double buff, double fac) {
    pg_params p;
    int rc = pg_params_default(&p);
    CHECK(rc == PG_OK, "pg_params_default: %s", pg_status_name(rc));
    p.lookahead = lookahead;
    p.buff = buff;
    p.fac = fac;
    return p;
}

static const char *method_name(int m) {
    switch (m) {
    case PG_METHOD_SAME_2D: return "detect_same_2d";
    case PG_METHOD_DIFF_2D: return "detect_diff_2d";
    case PG_METHOD_3D: return "detect_3d";
    default: return "none";
    }
}

static const char *entry_name(int k) {
    switch (k) {
    case PG_ENTRY_NEVER: return "never";
    case PG_ENTRY_ENTERS: return "enters";
    case PG_ENTRY_POSSIBLE: return "possible";
    default: return "?";
    }
}

/* The text after "key": in a JSON line (the CLI's flat answers), or NULL. */
static const char *json_value(const char *line, const char *key) {
    char pattern[64];
    const char *at;
    snprintf(pattern, sizeof pattern, "\"%s\":", key);
    at = strstr(line, pattern);
    return at ? at + strlen(pattern) : NULL;
}

static int json_is(const char *line, const char *key, const char *literal) {
    const char *v = json_value(line, key);
    return v != NULL && strncmp(v, literal, strlen(literal)) == 0;
}

/* The CLI's line agrees with this answer in every field; its floats read back to the
   same doubles (Rust prints the shortest string that reads back exactly). */
static void compare_with_cli(const char *line, const struct example *e, const pg_detection *d,
                             const pg_entry_time *t) {
    char quoted[96];
    const char *v;
    snprintf(quoted, sizeof quoted, "\"%s\"", e->id);
    CHECK(json_is(line, "id", quoted), "%s: the CLI's line is another case: %s", e->id, line);
    CHECK(json_is(line, "detected", d->detected ? "true" : "false"), "%s: detected", e->id);
    CHECK(json_is(line, "kind", d->kind == PG_KIND_EXACT ? "\"exact\"" : "\"conservative\""),
          "%s: kind", e->id);
    snprintf(quoted, sizeof quoted, "\"%s\"", method_name(d->method));
    CHECK(json_is(line, "decided_by", quoted), "%s: decided_by", e->id);
    CHECK(json_is(line, "well_formed", d->well_formed ? "true" : "false"), "%s: well_formed",
          e->id);
    snprintf(quoted, sizeof quoted, "\"%s\"", entry_name(t->kind));
    CHECK(json_is(line, "entry", quoted), "%s: entry", e->id);
    if (t->kind == PG_ENTRY_NEVER) {
        CHECK(json_value(line, "entry_lo") == NULL, "%s: the CLI gives entry_lo", e->id);
        return;
    }
    v = json_value(line, "entry_lo");
    CHECK(v != NULL && strtod(v, NULL) == t->lo, "%s: entry_lo %.17g vs the CLI's %s", e->id,
          t->lo, v ? v : "(none)");
    v = json_value(line, "entry_hi");
    CHECK(v != NULL && strtod(v, NULL) == t->hi, "%s: entry_hi %.17g vs the CLI's %s", e->id,
          t->hi, v ? v : "(none)");
}

static void test_examples(FILE *cli) {
    size_t i;
    char line[1024];
    for (i = 0; i < N_EXAMPLES; i++) {
        const struct example *e = &EXAMPLES[i];
        pg_params p = params_for(e->lookahead, e->buff, e->fac);
        pg_detection d;
        pg_entry_time t;
        int rc = pg_detect(&p, &e->point, &e->polygon, &d);
        CHECK(rc == PG_OK, "%s: pg_detect %s: %s", e->id, pg_status_name(rc), last_message());
        /* far from every threshold (no contact at all, or a clear entry): the truth is
           paper A's answer, and every comparison is decidable */
        CHECK(d.detected == e->enters, "%s: detected %d, the truth %d", e->id, d.detected,
              e->enters);
        CHECK(d.kind == PG_KIND_EXACT, "%s: kind %d", e->id, d.kind);
        CHECK(d.method == e->method, "%s: method %s, paper A's dispatch %s", e->id,
              method_name(d.method), method_name(e->method));
        CHECK(d.well_formed == 1 && d.well_formed_rule == 0, "%s: well_formed %d rule %d",
              e->id, d.well_formed, d.well_formed_rule);

        rc = pg_detect_time(&p, &e->point, &e->polygon, &t);
        CHECK(rc == PG_OK, "%s: pg_detect_time %s: %s", e->id, pg_status_name(rc),
              last_message());
        if (e->enters) {
            CHECK(t.kind == PG_ENTRY_ENTERS || t.kind == PG_ENTRY_POSSIBLE,
                  "%s: entry %s, the truth enters", e->id, entry_name(t.kind));
            CHECK(0.0 <= t.lo && t.lo <= e->entry && e->entry <= t.hi && t.hi <= e->lookahead,
                  "%s: [%.17g, %.17g] misses the entry %.17g", e->id, t.lo, t.hi, e->entry);
            /* an enclosure, not a guess: at most a few 2^-36 T wide when certified */
            if (t.kind == PG_ENTRY_ENTERS)
                CHECK(t.hi - t.lo <= 1e-9 * e->lookahead, "%s: [%.17g, %.17g] is wide", e->id,
                      t.lo, t.hi);
        } else {
            CHECK(t.kind == PG_ENTRY_NEVER, "%s: entry %s, the truth never", e->id,
                  entry_name(t.kind));
            CHECK(isnan(t.lo) && isnan(t.hi), "%s: never has NaN bounds", e->id);
        }
        if (cli != NULL) {
            if (fgets(line, sizeof line, cli) == NULL) {
                CHECK(0, "%s: the CLI's output ends early", e->id);
            } else {
                compare_with_cli(line, e, &d, &t);
            }
        }
    }
    if (cli != NULL)
        CHECK(fgets(line, sizeof line, cli) == NULL,
              "the CLI answers more cases than the %u embedded: %s", (unsigned)N_EXAMPLES,
              line);
}

/* ---- 2. bad input ------------------------------------------------------------- */

static void expect_error(int rc, int code, const char *prefix, const char *what) {
    const char *m = last_message();
    CHECK(rc == code, "%s: status %s, %s expected (%s)", what, pg_status_name(rc),
          pg_status_name(code), m);
    CHECK(starts_with(m, prefix), "%s: message \"%s\" does not start with \"%s\"", what, m,
          prefix);
}

static void test_bad_input(void) {
    pg_params p = params_for(10.0, 0.01, 0.0001);
    pg_point pt = P2(5.0, -3.0, 0.0, 1.0);
    pg_polygon sq = POLY(SQUARE, NULL, 4);
    pg_detection d;
    pg_entry_time t;
    pg_vec2 ring[4];
    pg_polygon bad;
    int rc;
    char small[10];

    rc = pg_detect(&p, NULL, &sq, &d);
    expect_error(rc, PG_ERR_NULL_POINTER, "point: NULL pointer", "NULL point");
    CHECK(d.detected == 1 && d.kind == PG_KIND_CONSERVATIVE && d.method == PG_METHOD_NONE,
          "an error still writes the conservative answer");
    expect_error(pg_detect(NULL, &pt, &sq, &d), PG_ERR_NULL_POINTER, "params: NULL pointer",
                 "NULL params");
    expect_error(pg_detect(&p, &pt, NULL, &d), PG_ERR_NULL_POINTER, "polygon: NULL pointer",
                 "NULL polygon");
    CHECK(pg_detect(&p, &pt, &sq, NULL) == PG_ERR_NULL_POINTER, "NULL out");
    bad = sq;
    bad.vertices = NULL;
    expect_error(pg_detect(&p, &pt, &bad, &d), PG_ERR_NULL_POINTER,
                 "polygon.vertices: NULL pointer", "NULL vertices");

    /* clockwise: the square listed backwards */
    ring[0] = SQUARE[3]; ring[1] = SQUARE[2]; ring[2] = SQUARE[1]; ring[3] = SQUARE[0];
    bad = sq;
    bad.vertices = ring;
    expect_error(pg_detect(&p, &pt, &bad, &d), PG_ERR_CLOCKWISE,
                 "polygon.vertices: clockwise order", "clockwise");

    /* NaN in vertex 2's y */
    memcpy(ring, SQUARE, sizeof ring);
    ring[2].y = nan("");
    expect_error(pg_detect(&p, &pt, &bad, &d), PG_ERR_NOT_FINITE,
                 "polygon.vertices[2][1]: not a finite number", "NaN vertex");
    rc = pg_detect_time(&p, &pt, &bad, &t);
    expect_error(rc, PG_ERR_NOT_FINITE, "polygon.vertices[2][1]", "NaN vertex, time");
    CHECK(t.kind == PG_ENTRY_POSSIBLE && t.lo == 0.0 && isinf(t.hi),
          "an error's entry time is possible on [0, inf]");

    pt.vel.x = INFINITY;
    expect_error(pg_detect(&p, &pt, &sq, &d), PG_ERR_NOT_FINITE, "point.vel", "infinite speed");
    pt.vel.x = 0.0;

    /* a bow tie: edges 0-1 and 2-3 cross */
    ring[0].x = 0.0; ring[0].y = 0.0; ring[1].x = 4.0; ring[1].y = 4.0;
    ring[2].x = 4.0; ring[2].y = 0.0; ring[3].x = 0.0; ring[3].y = 4.0;
    expect_error(pg_detect(&p, &pt, &bad, &d), PG_ERR_SELF_INTERSECTING,
                 "polygon.vertices: edges 0", "bow tie");

    bad = sq;
    bad.n = 2;
    expect_error(pg_detect(&p, &pt, &bad, &d), PG_ERR_TOO_FEW_VERTICES,
                 "polygon.vertices: 2 points, at least 3 are needed", "two vertices");

    p.buff = 0.0;
    expect_error(pg_detect(&p, &pt, &sq, &d), PG_ERR_BAD_PARAMETER, "buff: 0 is not > 0",
                 "zero buff");
    p.buff = 0.01;
    p.lookahead = -1.0;
    expect_error(pg_detect(&p, &pt, &sq, &d), PG_ERR_BAD_PARAMETER, "lookahead", "negative T");
    p.lookahead = 10.0;
    p.fac = 1.0;
    expect_error(pg_detect(&p, &pt, &sq, &d), PG_ERR_BAD_PARAMETER, "fac", "fac 1");
    p.fac = 0.0001;
    p.kappa_deg = nan("");
    expect_error(pg_detect(&p, &pt, &sq, &d), PG_ERR_NOT_FINITE, "kappa", "NaN kappa");
    p.kappa_deg = 5.0;
    {
        pg_params unset;
        pg_params_default(&unset);
        expect_error(pg_detect(&unset, &pt, &sq, &d), PG_ERR_BAD_PARAMETER, "buff",
                     "the defaults without buff");
    }

    pt.has_z = 1;
    expect_error(pg_detect(&p, &pt, &sq, &d), PG_ERR_DIMENSION_MISMATCH,
                 "polygon.bottom: 2D and 3D mixed", "3D point, 2D polygon");
    pt.has_z = 0;
    bad = sq;
    bad.has_slab = 1;
    bad.slab.bottom = 0.0;
    bad.slab.top = 10.0;
    expect_error(pg_detect(&p, &pt, &bad, &d), PG_ERR_DIMENSION_MISMATCH, "point.pos",
                 "2D point, 3D polygon");
    bad.slab.bottom = 11.0;
    pt.has_z = 1;
    expect_error(pg_detect(&p, &pt, &bad, &d), PG_ERR_SLAB_INVERTED, "polygon.top",
                 "inverted slab");
    pt.has_z = 0;

    /* the message is cut to the buffer, NUL-terminated, and says so */
    pg_detect(&p, NULL, &sq, &d);
    rc = pg_last_error_message(small, sizeof small);
    CHECK(rc == PG_ERR_CAPACITY && strlen(small) == sizeof small - 1,
          "truncated message: %s, \"%s\"", pg_status_name(rc), small);
    CHECK(pg_last_error_message(NULL, 4) == PG_ERR_NULL_POINTER, "NULL message buffer");
    /* a successful call clears it */
    CHECK(pg_detect(&p, &pt, &sq, &d) == PG_OK, "a good case after the bad ones");
    CHECK(strcmp(last_message(), "") == 0, "the message after success: %s", last_message());
    CHECK(strcmp(pg_status_name(PG_ERR_CLOCKWISE), "PG_ERR_CLOCKWISE") == 0, "status name");
    CHECK(strcmp(pg_status_name(12345), "unknown") == 0, "unknown status name");
}

/* ---- 3. batch ----------------------------------------------------------------- */

#define NPOLY 5
#define NPT 12

/* Five polygons in a row along x (at rest, drifting, warping) and twelve points that
   cross, graze or miss them. */
static pg_vec2 VERTS[64];
static pg_vec2 VELS[64];
static size_t OFFSETS[NPOLY + 1];
static pg_point POINTS[NPT];

static void build_batch(void) {
    size_t k = 0;
    int i;
    for (i = 0; i < NPOLY; i++) {
        double x = 10.0 * i;
        size_t n = (i % 2 == 0) ? 4 : 3, j;
        OFFSETS[i] = k;
        if (n == 4) {
            VERTS[k].x = x;       VERTS[k].y = 0.0;
            VERTS[k + 1].x = x + 4.0; VERTS[k + 1].y = 0.0;
            VERTS[k + 2].x = x + 4.0; VERTS[k + 2].y = 4.0;
            VERTS[k + 3].x = x;       VERTS[k + 3].y = 4.0;
        } else {
            VERTS[k].x = x;       VERTS[k].y = 0.0;
            VERTS[k + 1].x = x + 4.0; VERTS[k + 1].y = 0.0;
            VERTS[k + 2].x = x + 2.0; VERTS[k + 2].y = 3.0;
        }
        for (j = 0; j < n; j++) {
            /* polygon 0 rests, 1 drifts north, 2 grows about its corner 0, others drift */
            VELS[k + j].x = (i == 2) ? 0.05 * (VERTS[k + j].x - x) : (i == 0 ? 0.0 : -0.2);
            VELS[k + j].y = (i == 2) ? 0.05 * VERTS[k + j].y : (i == 1 ? 0.3 : 0.0);
        }
        k += n;
    }
    OFFSETS[NPOLY] = k;
    for (i = 0; i < NPT; i++) {
        POINTS[i].pos.x = -5.0 + 4.5 * i;
        POINTS[i].pos.y = (i % 3 == 0) ? -6.0 : (i % 3 == 1 ? 8.0 : 2.0);
        POINTS[i].vel.x = (i % 4 == 0) ? 1.0 : -0.5;
        POINTS[i].vel.y = (i % 3 == 0) ? 1.0 : (i % 3 == 1 ? -0.6 : 0.0);
        POINTS[i].has_z = 0;
        POINTS[i].z = 0.0;
        POINTS[i].vz = 0.0;
    }
}

static void test_batch(void) {
    pg_params p = params_for(12.0, 0.01, 0.0001);
    pg_polygons polys;
    pg_hit hits[NPOLY * NPT], first;
    size_t n_hits = 0, expected = 0, k = 0;
    int rc, i, j;

    build_batch();
    polys.vertices = VERTS;
    polys.velocities = VELS;
    polys.offsets = OFFSETS;
    polys.count = NPOLY;
    polys.slabs = NULL;

    rc = pg_detect_batch(&p, POINTS, NPT, &polys, hits, NPOLY * NPT, &n_hits);
    CHECK(rc == PG_OK, "pg_detect_batch: %s: %s", pg_status_name(rc), last_message());
    /* exactly pg_detect's detected pairs, in (point, polygon) order, same kind, method */
    for (i = 0; i < NPT; i++) {
        for (j = 0; j < NPOLY; j++) {
            pg_polygon one;
            pg_detection d;
            one.vertices = VERTS + OFFSETS[j];
            one.velocities = VELS + OFFSETS[j];
            one.n = OFFSETS[j + 1] - OFFSETS[j];
            one.has_slab = 0;
            rc = pg_detect(&p, &POINTS[i], &one, &d);
            CHECK(rc == PG_OK, "pair (%d, %d): %s", i, j, last_message());
            if (!d.detected)
                continue;
            expected++;
            CHECK(k < n_hits && hits[k].point == (size_t)i && hits[k].polygon == (size_t)j,
                  "pair (%d, %d) detected by pg_detect, not hit %u of the batch", i, j,
                  (unsigned)k);
            if (k < n_hits) {
                CHECK(hits[k].kind == d.kind && hits[k].method == d.method,
                      "pair (%d, %d): kind/method differ", i, j);
                if (hits[k].point == (size_t)i && hits[k].polygon == (size_t)j)
                    k++;
            }
        }
    }
    CHECK(n_hits == expected, "the batch has %u hits, pairwise %u", (unsigned)n_hits,
          (unsigned)expected);
    /* the workload is not trivial: some pairs hit, most do not */
    CHECK(expected >= 3 && expected < NPOLY * NPT / 2, "%u hits of %d pairs",
          (unsigned)expected, NPOLY * NPT);

    /* the capacity protocol: ask for the count, then a truncated prefix */
    rc = pg_detect_batch(&p, POINTS, NPT, &polys, NULL, 0, &n_hits);
    CHECK(rc == PG_ERR_CAPACITY && n_hits == expected, "cap 0: %s, %u", pg_status_name(rc),
          (unsigned)n_hits);
    rc = pg_detect_batch(&p, POINTS, NPT, &polys, &first, 1, &n_hits);
    CHECK(rc == PG_ERR_CAPACITY && n_hits == expected && first.point == hits[0].point &&
              first.polygon == hits[0].polygon,
          "cap 1: %s", pg_status_name(rc));
    rc = pg_detect_batch(&p, POINTS, NPT, &polys, hits, expected, &n_hits);
    CHECK(rc == PG_OK && n_hits == expected, "cap exact: %s", pg_status_name(rc));
    /* empty lists: no hits, no error */
    rc = pg_detect_batch(&p, NULL, 0, &polys, NULL, 0, &n_hits);
    CHECK(rc == PG_OK && n_hits == 0, "no points: %s", pg_status_name(rc));

    /* errors name the element */
    {
        pg_vec2 saved = VERTS[OFFSETS[2] + 1];
        VERTS[OFFSETS[2] + 1] = VERTS[OFFSETS[2] + 3];
        VERTS[OFFSETS[2] + 3] = saved; /* polygon 2 now runs 0, 3, 2, 1: clockwise */
        rc = pg_detect_batch(&p, POINTS, NPT, &polys, hits, NPOLY * NPT, &n_hits);
        expect_error(rc, PG_ERR_CLOCKWISE, "polygons[2].vertices: clockwise order",
                     "batch, clockwise polygon 2");
        CHECK(n_hits == 0, "an error's count is 0");
        VERTS[OFFSETS[2] + 3] = VERTS[OFFSETS[2] + 1];
        VERTS[OFFSETS[2] + 1] = saved;
    }
    POINTS[1].pos.y = nan("");
    expect_error(pg_detect_batch(&p, POINTS, NPT, &polys, hits, NPOLY * NPT, &n_hits),
                 PG_ERR_NOT_FINITE, "points[1].pos", "batch, NaN point 1");
    POINTS[1].pos.y = 8.0;
    {
        size_t saved = OFFSETS[2];
        OFFSETS[2] = OFFSETS[3] + 1;
        expect_error(pg_detect_batch(&p, POINTS, NPT, &polys, hits, NPOLY * NPT, &n_hits),
                     PG_ERR_WRONG_LENGTH, "polygons.offsets[3]", "batch, decreasing offsets");
        OFFSETS[2] = saved;
    }
    POINTS[0].has_z = 1;
    expect_error(pg_detect_batch(&p, POINTS, NPT, &polys, hits, NPOLY * NPT, &n_hits),
                 PG_ERR_DIMENSION_MISMATCH, "point.pos", "batch, 2D and 3D points");
    POINTS[0].has_z = 0;
    expect_error(pg_detect_batch(&p, POINTS, NPT, &polys, NULL, 5, &n_hits),
                 PG_ERR_NULL_POINTER, "hits: NULL pointer", "batch, NULL hits with cap 5");

    /* 3D: the two 3D examples' points against their slab */
    {
        pg_point pts3[2] = {P3(-3.0, 1.0, 20.0, 1.0, 0.0, -2.0),
                            P3(-3.0, 1.0, 20.0, 1.0, 0.0, -1.0)};
        size_t offs[2] = {0, 4};
        pg_slab slab = {0.0, 10.0, 0.0};
        pg_polygons one = {SQUARE, NULL, offs, 1, &slab};
        pg_params p3 = params_for(10.0, 0.01, 0.0001);
        rc = pg_detect_batch(&p3, pts3, 2, &one, hits, 2, &n_hits);
        CHECK(rc == PG_OK && n_hits == 1 && hits[0].point == 0 && hits[0].polygon == 0 &&
                  hits[0].method == PG_METHOD_3D,
              "3D batch: %s, %u hits", pg_status_name(rc), (unsigned)n_hits);
    }
}

/* ---- 4. intervals and keep-in exits ------------------------------------------- */

/* The spans of one relation: the count first (cap 0, out NULL), then exactly that many
   into `out` (room for `room`). Returns the count, or -1 after a failed check. */
static long spans_of(const pg_params *p, const pg_point *pt, const pg_polygon *poly,
                     int relation, pg_separation sep, pg_span *out, size_t room) {
    size_t n = 12345, m = 0, k;
    int rc = pg_intervals(p, pt, poly, relation, &sep, NULL, 0, &n);
    CHECK((rc == PG_OK && n == 0) || (rc == PG_ERR_CAPACITY && n > 0),
          "relation %d: the count: %s, %u", relation, pg_status_name(rc), (unsigned)n);
    if (n > room) {
        CHECK(0, "relation %d: %u spans, room for %u", relation, (unsigned)n, (unsigned)room);
        return -1;
    }
    rc = pg_intervals(p, pt, poly, relation, &sep, out, n, &m);
    CHECK(rc == PG_OK && m == n, "relation %d: %s (%s), %u spans", relation,
          pg_status_name(rc), last_message(), (unsigned)m);
    for (k = 0; k < n; k++) {
        CHECK(0.0 <= out[k].start_lo && out[k].start_lo <= out[k].start_hi &&
                  out[k].start_hi <= out[k].end_lo && out[k].end_lo <= out[k].end_hi &&
                  out[k].end_hi <= p->lookahead,
              "relation %d: span %u is not ordered in [0, T]", relation, (unsigned)k);
        if (k > 0)
            CHECK(out[k - 1].end_hi <= out[k].start_lo, "relation %d: spans %u, %u overlap",
                  relation, (unsigned)k - 1, (unsigned)k);
    }
    return (long)n;
}

/* A certain span whose start encloses a and end encloses b, each at most 1e-9 T wide. */
static void check_span(const char *what, const pg_span *s, double a, double b, double t) {
    CHECK(s->certain == 1, "%s: not certain", what);
    CHECK(s->start_lo <= a && a <= s->start_hi && s->start_hi - s->start_lo <= 1e-9 * t,
          "%s: start [%.17g, %.17g] does not enclose %.17g narrowly", what, s->start_lo,
          s->start_hi, a);
    CHECK(s->end_lo <= b && b <= s->end_hi && s->end_hi - s->end_lo <= 1e-9 * t,
          "%s: end [%.17g, %.17g] does not enclose %.17g narrowly", what, s->end_lo, s->end_hi,
          b);
}

static void test_intervals(void) {
    pg_span out[8];
    pg_detection d;
    size_t n;
    int rc;

    /* (1, -2) moving north at 1 across the 2x2 square at rest: inside on [2, 4]; within
       D = 0.5 on [1.5, 4.5]; more than 0.5 inside (x = 1 is 1 from the sides) only for
       y = -2 + t in (0.5, 1.5), so breach_0.5 is [0, 2.5] and [3.5, 10]. */
    {
        pg_params p = params_for(10.0, 0.01, 0.0001);
        pg_point pt = P2(1.0, -2.0, 0.0, 1.0);
        pg_polygon sq = POLY(SQUARE, NULL, 4);
        pg_separation none = {0.0, 0.0}, half = {0.5, 0.0};
        if (spans_of(&p, &pt, &sq, PG_RELATION_INSIDE, none, out, 8) == 1)
            check_span("square, inside", &out[0], 2.0, 4.0, 10.0);
        if (spans_of(&p, &pt, &sq, PG_RELATION_NEAR, half, out, 8) == 1)
            check_span("square, near 0.5", &out[0], 1.5, 4.5, 10.0);
        if (spans_of(&p, &pt, &sq, PG_RELATION_BREACH, half, out, 8) == 2) {
            check_span("square, breach 0.5 (1)", &out[0], 0.0, 2.5, 10.0);
            check_span("square, breach 0.5 (2)", &out[1], 3.5, 10.0, 10.0);
            CHECK(out[0].start_lo == 0.0 && out[0].start_hi == 0.0 && out[1].end_lo == 10.0 &&
                      out[1].end_hi == 10.0,
                  "square, breach: the ends at 0 and T are exact");
        }
        rc = pg_detect_exit(&p, &pt, &sq, &half, &d);
        CHECK(rc == PG_OK && d.detected == 1 && d.kind == PG_KIND_EXACT,
              "square: the point starts outside, so it exits: %s, %d", pg_status_name(rc),
              d.detected);

        /* the buffer protocol: room for 1 of the 2 breach spans */
        rc = pg_intervals(&p, &pt, &sq, PG_RELATION_BREACH, &half, out, 1, &n);
        CHECK(rc == PG_ERR_CAPACITY && n == 2, "cap 1: %s, %u", pg_status_name(rc),
              (unsigned)n);
        CHECK(out[0].start_lo == 0.0 && out[0].end_lo <= 2.5 && 2.5 <= out[0].end_hi,
              "cap 1: the first span is written");
        CHECK(starts_with(last_message(), "out: 2 spans, room for 1"), "cap 1: %s",
              last_message());
        CHECK(strcmp(pg_status_name(PG_ERR_CAPACITY), "PG_ERR_CAPACITY") == 0,
              "status name");

        /* errors name the field; the answer left is one possible span over all time */
        {
            pg_separation neg = {-1.0, 0.0}, nan_h = {1.0, 0.0};
            nan_h.h = nan("");
            rc = pg_intervals(&p, &pt, &sq, PG_RELATION_NEAR, &neg, out, 8, &n);
            expect_error(rc, PG_ERR_BAD_PARAMETER, "sep.d: ", "negative D");
            CHECK(n == 1 && out[0].certain == 0 && out[0].start_lo == 0.0 &&
                      isinf(out[0].end_hi),
                  "an error leaves one possible span over [0, inf]");
            expect_error(pg_intervals(&p, &pt, &sq, PG_RELATION_NEAR, &nan_h, out, 8, &n),
                         PG_ERR_NOT_FINITE, "sep.h: not a finite number", "NaN H");
            expect_error(pg_intervals(&p, &pt, &sq, 3, &half, out, 8, &n), PG_ERR_BAD_PARAMETER,
                         "relation: 3 is not", "relation 3");
            expect_error(pg_intervals(&p, &pt, &sq, PG_RELATION_NEAR, NULL, out, 8, &n),
                         PG_ERR_NULL_POINTER, "sep: NULL pointer", "NULL sep");
            expect_error(pg_intervals(&p, &pt, &sq, PG_RELATION_NEAR, &half, NULL, 8, &n),
                         PG_ERR_NULL_POINTER, "out: NULL pointer", "NULL out, cap 8");
            CHECK(pg_intervals(&p, &pt, &sq, PG_RELATION_NEAR, &half, out, 8, NULL) ==
                      PG_ERR_NULL_POINTER,
                  "NULL n_out");
            rc = pg_detect_exit(&p, &pt, &sq, &neg, &d);
            expect_error(rc, PG_ERR_BAD_PARAMETER, "sep.d: ", "exit, negative D");
            CHECK(d.detected == 1 && d.kind == PG_KIND_CONSERVATIVE,
                  "an exit error still says detected");
        }
    }

    /* examples/intervals.jsonl, "cell-entered-twice": the U-shaped cell drifts west at 60,
       the point flies east at 480 along y = 30, so the relative x is 540 t. At y = 30 the
       walls are x in [40, 55] and [85, 100]: inside on [40, 55]/540 and [85, 100]/540;
       within D = 5 on [35, 60]/540 and [80, 105]/540; more than 5 inside (the slot's floor
       y = 20 is 10 away) only for x in (45, 50) and (90, 95): breach_5 is [0, 45]/540,
       [50, 90]/540 and [95/540, 0.25]. */
    {
        static const pg_vec2 CELL[8] = {{40.0, 0.0},  {100.0, 0.0}, {100.0, 50.0},
                                        {85.0, 50.0}, {85.0, 20.0}, {55.0, 20.0},
                                        {55.0, 50.0}, {40.0, 50.0}};
        static const pg_vec2 WEST[8] = {{-60.0, 0.0}, {-60.0, 0.0}, {-60.0, 0.0},
                                        {-60.0, 0.0}, {-60.0, 0.0}, {-60.0, 0.0},
                                        {-60.0, 0.0}, {-60.0, 0.0}};
        pg_params p = params_for(0.25, 0.5, 0.0001);
        pg_point pt = P2(0.0, 30.0, 480.0, 0.0);
        pg_polygon cell = POLY(CELL, WEST, 8);
        pg_separation five = {5.0, 0.0};
        if (spans_of(&p, &pt, &cell, PG_RELATION_INSIDE, five, out, 8) == 2) {
            check_span("cell, inside (1)", &out[0], 40.0 / 540, 55.0 / 540, 0.25);
            check_span("cell, inside (2)", &out[1], 85.0 / 540, 100.0 / 540, 0.25);
        } else {
            CHECK(0, "cell: inside is two spans");
        }
        if (spans_of(&p, &pt, &cell, PG_RELATION_NEAR, five, out, 8) == 2) {
            check_span("cell, near 5 (1)", &out[0], 35.0 / 540, 60.0 / 540, 0.25);
            check_span("cell, near 5 (2)", &out[1], 80.0 / 540, 105.0 / 540, 0.25);
        } else {
            CHECK(0, "cell: near is two spans");
        }
        if (spans_of(&p, &pt, &cell, PG_RELATION_BREACH, five, out, 8) == 3) {
            check_span("cell, breach 5 (1)", &out[0], 0.0, 45.0 / 540, 0.25);
            check_span("cell, breach 5 (2)", &out[1], 50.0 / 540, 90.0 / 540, 0.25);
            check_span("cell, breach 5 (3)", &out[2], 95.0 / 540, 0.25, 0.25);
        } else {
            CHECK(0, "cell: breach is three spans");
        }
    }

    /* examples/intervals.jsonl, "drone-leaves-through-ceiling": the 100 x 100 box from
       z = 0 to 120 at rest, the drone at (50, 50, 100) moving (1, 0, 2), D = H = 10. Its
       height reaches the ceiling 120 at t = 10 (inside [0, 10]), 130 at t = 15 (near
       [0, 15]) and 110 = ceiling - H at t = 5, while x = 50 + t stays more than 10 from
       the walls until t = 40 (breach [5, 60]): it exits. Until T = 4 it does not. */
    {
        static const pg_vec2 BOX[4] = {{0.0, 0.0}, {100.0, 0.0}, {100.0, 100.0}, {0.0, 100.0}};
        pg_params p = params_for(60.0, 1.0, 0.0001);
        pg_point pt = P3(50.0, 50.0, 100.0, 1.0, 0.0, 2.0);
        pg_polygon box = POLY3(BOX, NULL, 4, 0.0, 120.0, 0.0);
        pg_separation ten = {10.0, 10.0};
        if (spans_of(&p, &pt, &box, PG_RELATION_INSIDE, ten, out, 8) == 1)
            check_span("drone, inside", &out[0], 0.0, 10.0, 60.0);
        else
            CHECK(0, "drone: inside is one span");
        if (spans_of(&p, &pt, &box, PG_RELATION_NEAR, ten, out, 8) == 1)
            check_span("drone, near 10", &out[0], 0.0, 15.0, 60.0);
        else
            CHECK(0, "drone: near is one span");
        if (spans_of(&p, &pt, &box, PG_RELATION_BREACH, ten, out, 8) == 1)
            check_span("drone, breach 10", &out[0], 5.0, 60.0, 60.0);
        else
            CHECK(0, "drone: breach is one span");
        rc = pg_detect_exit(&p, &pt, &box, &ten, &d);
        CHECK(rc == PG_OK && d.detected == 1 && d.kind == PG_KIND_EXACT &&
                  d.method == PG_METHOD_3D,
              "drone: exits (%s, %d, kind %d)", pg_status_name(rc), d.detected, d.kind);
        p.lookahead = 4.0;
        rc = pg_detect_exit(&p, &pt, &box, &ten, &d);
        CHECK(rc == PG_OK && d.detected == 0 && d.kind == PG_KIND_EXACT,
              "drone until T = 4: no exit (%s, %d)", pg_status_name(rc), d.detected);
        CHECK(spans_of(&p, &pt, &box, PG_RELATION_BREACH, ten, out, 8) == 0,
              "drone until T = 4: no breach");
    }
}

#define MOVING_DATA "crates/earth/tests/data/moving/"

/* The whole of a file, NUL-terminated (NULL when it cannot be read); *len its bytes. */
static char *read_file(const char *path, size_t *len) {
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    size_t cap = 0, n = 0;
    if (f == NULL)
        return NULL;
    for (;;) {
        if (n + 4096 + 1 > cap) {
            char *grown;
            cap = 2 * cap + 4096 + 1;
            grown = realloc(buf, cap);
            if (grown == NULL) {
                free(buf);
                fclose(f);
                return NULL;
            }
            buf = grown;
        }
        size_t got = fread(buf + n, 1, 4096, f);
        n += got;
        if (got < 4096)
            break;
    }
    fclose(f);
    buf[n] = '\0';
    *len = n;
    return buf;
}

static size_t count_lines(const char *s) {
    size_t n = 0;
    for (; *s; s++)
        n += *s == '\n';
    return n;
}

static void test_encounters(const char *cli_path) {
    size_t movers_len = 0, areas_len = 0, want_len = 0, out_len = 99;
    char *movers = read_file(MOVING_DATA "quickstart-3.csv", &movers_len);
    char *areas = read_file(MOVING_DATA "cells-2.mf.json", &areas_len);
    char *out = NULL;
    pg_encounter_options opts;
    int rc;
    CHECK(movers != NULL && areas != NULL, "the test data (run from the repository's root)");
    if (movers == NULL || areas == NULL) {
        free(movers);
        free(areas);
        return;
    }
    CHECK(pg_encounter_options_default(&opts) == PG_OK, "defaults");
    CHECK(opts.max_gap_s == 60.0 && opts.geodesy == PG_GEODESY_SPHERE, "defaults");
    opts.sep_nm = 5.0;
    opts.sep_v_ft = 1000.0;
    rc = pg_encounters(movers, movers_len, 1, areas, areas_len, &opts, &out, &out_len);
    CHECK(rc == PG_OK, "pg_encounters: %s %s", pg_status_name(rc), last_message());
    CHECK(out != NULL && strlen(out) == out_len, "the text and its length");
    /* two flights reach the cells within 5 nm; one of them meets both cells */
    CHECK(out != NULL && count_lines(out) == 3, "3 lines, not %zu", out ? count_lines(out) : 0);
    CHECK(out != NULL && starts_with(out, "{\"mover\":\"ABR471_198\""), "%.40s", out);
    if (cli_path != NULL && out != NULL) {
        char *want = read_file(cli_path, &want_len);
        CHECK(want != NULL, "cannot read %s", cli_path);
        CHECK(want != NULL && want_len == out_len && memcmp(want, out, out_len) == 0,
              "the lines differ from the CLI's:\n%s\nCLI:\n%s", out, want ? want : "");
        free(want);
    }
    pg_free_text(out);
    pg_free_text(NULL);

    /* statuses: the text and its length are NULL and 0 on each */
    out = (char *)movers;
    rc = pg_encounters(NULL, 0, 1, areas, areas_len, NULL, &out, &out_len);
    expect_error(rc, PG_ERR_NULL_POINTER, "movers", "NULL movers");
    CHECK(out == NULL && out_len == 0, "NULL and 0 written on an error");
    rc = pg_encounters(movers, movers_len, 1, areas, areas_len, NULL, NULL, &out_len);
    expect_error(rc, PG_ERR_NULL_POINTER, "out", "NULL out");
    rc = pg_encounters("\xff\xfe", 2, 0, areas, areas_len, NULL, &out, &out_len);
    expect_error(rc, PG_ERR_UTF8, "movers", "bad UTF-8");
    rc = pg_encounters(movers, movers_len, 1, "not json", 8, NULL, &out, &out_len);
    expect_error(rc, PG_ERR_INPUT, "areas", "areas that are not JSON");
    rc = pg_encounters("no,header\n", 10, 1, areas, areas_len, NULL, &out, &out_len);
    expect_error(rc, PG_ERR_INPUT, "movers", "a CSV without the required columns");
    opts.sep_nm = -1.0;
    rc = pg_encounters(movers, movers_len, 1, areas, areas_len, &opts, &out, &out_len);
    expect_error(rc, PG_ERR_BAD_PARAMETER, "sep_nm", "a negative separation");
    opts.sep_nm = 5.0;
    opts.geodesy = 7;
    rc = pg_encounters(movers, movers_len, 1, areas, areas_len, &opts, &out, &out_len);
    expect_error(rc, PG_ERR_BAD_PARAMETER, "geodesy", "an unknown geodesy");

    /* a row with a latitude out of range: rejected and named, the rest answered */
    {
        const char *bad = "timestamp,icao24,latitude,longitude\n"
                          "0,abc,95,2\n10,abc,45,2\n20,abc,45.1,2.1\n";
        rc = pg_encounters(bad, strlen(bad), 1, areas, areas_len, NULL, &out, &out_len);
        CHECK(rc == PG_PARTIAL, "%s", pg_status_name(rc));
        CHECK(starts_with(last_message(), "movers: line 2"), "%s", last_message());
        CHECK(out != NULL && out_len == 0, "an empty answer, still a text");
        pg_free_text(out);
    }
    free(movers);
    free(areas);
}

/* ---- 6. the way out ----------------------------------------------------------- */

/* The distance from x to the segment a b, in plain f64 (a check, not a certificate). */
static double seg_dist(pg_vec2 x, pg_vec2 a, pg_vec2 b) {
    double ex = b.x - a.x, ey = b.y - a.y;
    double u = ((x.x - a.x) * ex + (x.y - a.y) * ey) / (ex * ex + ey * ey);
    double px, py;
    if (u < 0.0)
        u = 0.0;
    if (u > 1.0)
        u = 1.0;
    px = a.x + u * ex - x.x;
    py = a.y + u * ey - x.y;
    return sqrt(px * px + py * py);
}

/* The distance from x to the boundary of the ring. */
static double ring_dist(pg_vec2 x, const pg_vec2 *v, size_t n) {
    double best = INFINITY;
    size_t i;
    for (i = 0; i < n; i++) {
        double d = seg_dist(x, v[i], v[(i + 1) % n]);
        if (d < best)
            best = d;
    }
    return best;
}

/* Is x strictly inside the ring (crossing parity)? */
static int ring_inside(pg_vec2 x, const pg_vec2 *v, size_t n) {
    int in = 0;
    size_t i;
    for (i = 0; i < n; i++) {
        pg_vec2 a = v[i], b = v[(i + 1) % n];
        if ((a.y > x.y) != (b.y > x.y) && x.x < a.x + (x.y - a.y) * (b.x - a.x) / (b.y - a.y))
            in = !in;
    }
    return in;
}

static void test_wayout(void) {
    /* the square [3, 5] x [-1, 1] at rest east of the point, D = 0.5, T = 10, speed 1 */
    static const pg_vec2 sq[4] = {{3.0, -1.0}, {5.0, -1.0}, {5.0, 1.0}, {3.0, 1.0}};
    static const size_t offsets[2] = {0, 4};
    pg_polygons obstacles = {sq, NULL, offsets, 1, NULL};
    pg_polygon polygon = POLY(sq, NULL, 4);
    pg_point point = P2(0.0, 0.0, 0.0, 0.0);
    pg_separation sep = {0.5, 0.0};
    pg_params params = params_for(10.0, 1.0, 0.0001);
    pg_band bands[256], small[2];
    pg_bands_info info, info2;
    pg_span spans[8];
    pg_recovery_point rec;
    pg_ring rings[4];
    pg_vec2 verts[512];
    pg_shape_info shape;
    size_t k, clear = 0, conflict = 0;
    int rc;

    rc = pg_course_bands(&point, &obstacles, 10.0, &sep, 1.0, 0.01, bands, 256, &info);
    CHECK(rc == PG_OK, "pg_course_bands: %s %s", pg_status_name(rc), last_message());
    CHECK(info.count >= 3 && info.count <= 256, "%u bands", (unsigned)info.count);
    CHECK(info.met == 1 && info.unknown_total <= 0.01, "unknown %g", info.unknown_total);
    CHECK(bands[0].lo == 0.0 && bands[info.count - 1].hi == 2.0 * M_PI_VALUE, "the tiling");
    for (k = 0; k < info.count && k < 256; k++) {
        double mid = 0.5 * (bands[k].lo + bands[k].hi);
        long n;
        if (k > 0)
            CHECK(bands[k].lo == bands[k - 1].hi, "band %u does not start where %u ends",
                  (unsigned)k, (unsigned)k - 1);
        if (bands[k].kind == PG_BAND_UNKNOWN)
            continue;
        point.vel.x = sin(mid);
        point.vel.y = cos(mid);
        n = spans_of(&params, &point, &polygon, PG_RELATION_NEAR, sep, spans, 8);
        if (bands[k].kind == PG_BAND_CLEAR) {
            clear++;
            CHECK(n == 0, "course %.6f in a clear band: %ld spans of near_D", mid, n);
        } else {
            conflict++;
            CHECK(n >= 1 && spans[0].certain == 1,
                  "course %.6f in a conflict band: no certain span", mid);
        }
    }
    CHECK(clear >= 1 && conflict >= 1, "%u clear, %u conflict bands", (unsigned)clear,
          (unsigned)conflict);
    /* east (pi/2) heads into the square */
    for (k = 0; k < info.count; k++)
        if (bands[k].lo <= M_PI_VALUE / 2 && M_PI_VALUE / 2 <= bands[k].hi)
            CHECK(bands[k].kind == PG_BAND_CONFLICT, "east is not in conflict");

    /* a buffer too small: the first two bands, the whole count, PG_ERR_CAPACITY */
    rc = pg_course_bands(&point, &obstacles, 10.0, &sep, 1.0, 0.01, small, 2, &info2);
    CHECK(rc == PG_ERR_CAPACITY, "%s", pg_status_name(rc));
    CHECK(info2.count == info.count, "the count %u", (unsigned)info2.count);
    for (k = 0; k < 2; k++) /* field by field: the structs' padding is not written */
        CHECK(small[k].lo == bands[k].lo && small[k].hi == bands[k].hi &&
                  small[k].kind == bands[k].kind,
              "band %u of the small buffer", (unsigned)k);
    rc = pg_course_bands(&point, &obstacles, 10.0, &sep, -1.0, 0.01, small, 2, &info2);
    expect_error(rc, PG_ERR_BAD_PARAMETER, "speed", "a negative speed");
    CHECK(info2.count == 1 && small[0].kind == PG_BAND_UNKNOWN, "the conservative band");

    /* speed bands due east over [0, 2]: speed 0 never moves (clear: 3 - 0.5 away) */
    rc = pg_speed_bands(&point, &obstacles, 10.0, &sep, M_PI_VALUE / 2, 0.0, 2.0, 0.01, bands,
                        256, &info);
    CHECK(rc == PG_OK, "pg_speed_bands: %s %s", pg_status_name(rc), last_message());
    CHECK(bands[0].lo == 0.0 && bands[0].kind == PG_BAND_CLEAR, "speed 0 is clear");
    CHECK(bands[info.count - 1].hi == 2.0 && bands[info.count - 1].kind == PG_BAND_CONFLICT,
          "speed 2 east is in conflict");

    /* recovery: from inside the buffer out to D, by a plain distance */
    {
        pg_vec2 s = {2.8, 0.3};
        rc = pg_recovery(&polygon, 0.0, s, 0.5, PG_FENCE_KEEP_OUT, &rec);
        CHECK(rc == PG_OK && rec.kind == PG_RECOVERY_POINT, "%s", pg_status_name(rc));
        CHECK(ring_dist(rec.x, sq, 4) >= 0.5 && !ring_inside(rec.x, sq, 4),
              "the point (%.17g, %.17g) is not D away", rec.x.x, rec.x.y);
        CHECK(rec.min_lo <= 0.3 && 0.3 <= rec.dist_hi && rec.dist_hi - rec.min_lo < 1e-6,
              "the distance [%g, %g] does not enclose 0.3", rec.min_lo, rec.dist_hi);
        rc = pg_recovery(&polygon, 0.0, s, 0.5, PG_FENCE_KEEP_IN, &rec);
        CHECK(rc == PG_OK && rec.kind == PG_RECOVERY_POINT, "%s", pg_status_name(rc));
        CHECK(ring_inside(rec.x, sq, 4) && ring_dist(rec.x, sq, 4) >= 0.5, "not in the core");
        rc = pg_recovery(&polygon, 0.0, s, 1.5, PG_FENCE_KEEP_IN, &rec);
        CHECK(rc == PG_OK && rec.kind == PG_RECOVERY_IMPOSSIBLE, "inradius 1 < 1.5");
        rc = pg_recovery(&polygon, 0.0, s, 0.5, 3, &rec);
        expect_error(rc, PG_ERR_BAD_PARAMETER, "fence", "an unknown fence");
        CHECK(rec.kind == PG_RECOVERY_NONE, "no answer on an error");
    }

    /* offset by 0.5 within 1 %: one ring, points at distance 0.5 inside, vertices within
       0.505 */
    rc = pg_offset(&polygon, 0.0, 0.5, 0.01, NULL, 0, NULL, 0, &shape);
    CHECK(rc == PG_ERR_CAPACITY && shape.regions == 1 && shape.rings == 1, "sizes %s",
          pg_status_name(rc));
    rc = pg_offset(&polygon, 0.0, 0.5, 0.01, rings, 4, verts, 512, &shape);
    CHECK(rc == PG_OK, "pg_offset: %s %s", pg_status_name(rc), last_message());
    if (rc == PG_OK) {
        for (k = 0; k < shape.vertices; k++)
            CHECK(ring_dist(verts[k], sq, 4) <= 0.5 * 1.01, "vertex %u too far", (unsigned)k);
        for (k = 0; k < 64; k++) {
            double a = 2.0 * M_PI_VALUE * (double)k / 64.0;
            pg_vec2 c = sq[(k / 16) % 4];
            pg_vec2 x;
            x.x = c.x + 0.5 * cos(a);
            x.y = c.y + 0.5 * sin(a);
            if (ring_dist(x, sq, 4) >= 0.5 * (1.0 - 1e-12))
                CHECK(ring_inside(x, verts + rings[0].first, rings[0].n),
                      "(%g, %g) at distance 0.5 is outside the offset", x.x, x.y);
        }
    }
    rc = pg_offset(&polygon, 0.0, 0.5, 0.01, rings, 1, verts, 4, &shape);
    CHECK(rc == PG_ERR_CAPACITY && shape.vertices > 4, "a small vertex buffer");
    rc = pg_inset(&polygon, 0.0, 1.5, 0.01, rings, 4, verts, 512, &shape);
    CHECK(rc == PG_OK && shape.regions == 0 && shape.rings == 0, "the empty inset");
    rc = pg_offset(&polygon, 0.0, 0.5, 0.0, rings, 4, verts, 512, &shape);
    expect_error(rc, PG_ERR_BAD_PARAMETER, "eps", "eps 0");
}

int main(int argc, char **argv) {
    FILE *cli = NULL;
    const char *encounters_cli = NULL;
    int k;
    for (k = 1; k + 1 < argc; k += 2) {
        if (strcmp(argv[k], "--cli") == 0 && cli == NULL) {
            cli = fopen(argv[k + 1], "r");
            if (cli == NULL) {
                fprintf(stderr, "cannot read %s\n", argv[k + 1]);
                return 2;
            }
        } else if (strcmp(argv[k], "--encounters-cli") == 0) {
            encounters_cli = argv[k + 1];
        } else {
            break;
        }
    }
    if (k != argc) {
        fprintf(stderr,
                "usage: %s [--cli FILE] [--encounters-cli FILE]  (FILE: polyguard detect "
                "--time output; polyguard encounters output)\n",
                argv[0]);
        return 2;
    }
    test_examples(cli);
    if (cli != NULL)
        fclose(cli);
    test_bad_input();
    test_batch();
    test_intervals();
    test_encounters(encounters_cli);
    test_wayout();
    printf("%d checks, %d failed%s\n", checks, failures,
           cli != NULL ? " (examples also compared with the CLI)" : "");
    return failures == 0 ? 0 : 1;
}
