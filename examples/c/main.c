// rastercheck's C example rasterizer: a correct-by-construction
// fixed-point rasterizer, the kind a driver engineer writes, judged by
// rastercheck through its external-process protocol, version 2, in
// persistent mode (SPEC.md §12.4, §12.7).
//
// Build and run (from the repository root):
//
//     mkdir -p out
//     cc -std=c99 -O2 -Wall -Wextra -Werror -o out/c_rasterizer examples/c/*.c -lm
//     rastercheck run cases -r 'c=external-persistent:out/c_rasterizer'
//
// What it is meant to show: that exact rasterization needs no big numbers.
// Every vertex is snapped from its exact decimal or fraction spelling to
// the case's subpixel grid (ties to even, fixed.c); every sample lies on a
// 2^-16 pixel grid; every coverage decision (edge functions, the fill
// rule's ties, cull, polygon winding numbers, a moving vertex at an
// instant u/65536 of the shutter) is the sign of a 128-bit integer
// expression (coverage.c). Only depth and attributes, which are judged
// within a tolerance, are computed in doubles (draw.c). So it should pass
// every triangle, polygon and antialiasing case it declares; a failure is
// a bug in it or in rastercheck.
//
// It draws triangles and polygons (nonzero, even-odd), at the pixel centre
// or at the request's sample offsets, under all five fill rules, and
// moving triangles at the request's instants; points (SPEC.md §17);
// clip-space triangles and points (§16, §12.10) under the case's own clip
// conventions, clipping exactly in 128-bit rationals (rational.c), with
// depth formats and polygon offset (§18). A piece of a triangle with a
// vertex behind the eye is tested by §16.4's homogeneous edge functions,
// and the per-sample depth test is made, in exact rationals too. Where its
// arithmetic cannot be exact (past 128-bit rationals, a projected point
// off the 2^-16 grid at exact coordinates) it answers unsupported. It does not draw lines: its
// hello says so, and rastercheck reports such cases unsupported.
//
// Files: main.c (the protocol: hello, one answer line per request, ids),
// draw.c (a request into fragments), clip.c (clip space and points),
// scene.h (what draw.c and clip.c share), coverage.c (exact coverage tests),
// fixed.c (exact spellings to fixed point), rational.c (exact rationals for
// clip space), json.c (a minimal JSON reader),
// buffer.c (a growable text buffer). C99 and the standard library, plus
// GCC/Clang's __int128.
//
// Flags: --wrong-tie plants a bug (every tie goes to the opposite edges:
// bottom-right for a top-left case), for the test that rastercheck catches
// it; --no-motion declares and draws no moving scenes; --ignore-offset
// plants another (it declares polygon offset and draws every depth without
// it), --no-offset declares no polygon offset; --fixed-clip clips every
// case before the divide against all six planes (clip_xy and clip_z
// clip-then-snap), whatever it states, and declares so in its hello's
// conventions, as a pipeline that cannot choose does (SPEC.md §16.9);
// --fixed-clip-undeclared clips so without declaring it (a planted bug).
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "buffer.h"
#include "draw.h"
#include "json.h"

/* Whether this build declares moving scenes (SPEC.md §12.8) by default. */
#define MOTION_BY_DEFAULT 1

/* The hello (SPEC.md §12.7): what this program draws. Cases outside it are
 * reported unsupported by rastercheck and never sent. */
static void hello(int motion, int offset, int fixed_clip) {
    printf("{\"hello\":{\"protocol\":2,\"name\":\"c-example\",\"version\":\"1\","
           "\"capabilities\":{\"primitives\":[\"triangles\",\"polygons\",\"lines\",\"points\"],"
           "\"line_rules\":[\"parallelogram\"],"
           "\"polygon_fills\":[\"nonzero\",\"even-odd\"],"
           "\"fill_rules\":[\"top-left\",\"bottom-right\",\"top-right\",\"bottom-left\",\"all-edges\"],"
           "\"interpolation\":[\"flat\",\"linear\",\"perspective\"],"
           "\"max_subpixel_bits\":16,\"exact_coordinates\":true,"
           "\"antialias\":true,\"max_samples\":256,"
           "\"depth\":true,\"attributes\":true,\"motion\":%s,"
           "\"clip_space\":true,\"depth_formats\":[\"unorm16\",\"unorm24\",\"float32\"],"
           "\"polygon_offset\":%s},"
           "\"conventions\":{\"arithmetic\":\"exact: 128-bit integers on a 2^-16 pixel grid\","
           "%s\"interpolation\":\"doubles\"}}}\n",
           motion ? "true" : "false", offset ? "true" : "false",
           fixed_clip ? "\"clip_xy\":\"clip-then-snap\",\"clip_z\":\"clip-then-snap\"," : "");
    fflush(stdout);
}

/* One line of stdin, without its newline, in a buffer that grows; NULL at
 * end of input. */
static char *read_line(char **line, size_t *capacity) {
    size_t length = 0;
    int c;
    while ((c = getchar()) != EOF && c != '\n') {
        if (length + 2 > *capacity) {
            size_t grown_capacity = *capacity ? *capacity * 2 : 65536;
            char *grown = realloc(*line, grown_capacity);
            if (!grown) return NULL;
            *line = grown;
            *capacity = grown_capacity;
        }
        (*line)[length++] = (char)c;
    }
    if (c == EOF && length == 0) return NULL;
    if (!*line && !(*line = malloc(*capacity = 1))) return NULL;
    (*line)[length] = '\0';
    return *line;
}

int main(int argc, char **argv) {
    options opt = {0};
    int motion = MOTION_BY_DEFAULT, silent_clip = 0, i;
    char *line = NULL, why[512];
    size_t capacity = 0;
    buffer answer = {0}, body = {0};
    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--wrong-tie") == 0) opt.wrong_tie = 1;
        else if (strcmp(argv[i], "--no-motion") == 0) motion = 0;
        else if (strcmp(argv[i], "--ignore-offset") == 0) opt.ignore_offset = opt.claim_offset = 1;
        else if (strcmp(argv[i], "--no-offset") == 0) opt.ignore_offset = 1;
        else if (strcmp(argv[i], "--fixed-clip") == 0) opt.fixed_clip = 1;
        else if (strcmp(argv[i], "--fixed-clip-undeclared") == 0) opt.fixed_clip = silent_clip = 1;
        else {
            fprintf(stderr, "c_rasterizer: unknown argument %s (known: --wrong-tie, --no-motion, --ignore-offset, --no-offset, --fixed-clip, "
                    "--fixed-clip-undeclared)\n",
                    argv[i]);
            return 2;
        }
    }
    hello(motion, !opt.ignore_offset || opt.claim_offset, opt.fixed_clip && !silent_clip);
    while (read_line(&line, &capacity)) {
        size_t error_at = 0;
        json *request;
        const json *id;
        if (line[0] == '\0') continue; /* blank lines are no requests */
        request = json_parse(line, &error_at);
        id = json_get(request, "id");
        buffer_clear(&answer);
        buffer_clear(&body);
        buffer_printf(&answer, "{");
        if (id && id->kind == JSON_STRING) {
            buffer_printf(&answer, "\"id\":");
            buffer_json_string(&answer, id->text);
            buffer_printf(&answer, ",");
        }
        if (!request) {
            snprintf(why, sizeof why, "the request is not JSON (at byte %lu)", (unsigned long)error_at);
            buffer_printf(&answer, "\"error\":");
            buffer_json_string(&answer, why);
        } else if (json_get(request, "bye")) {
            json_free(request);
            break;
        } else if (json_get(json_get(request, "plan"), "motion") && !motion) {
            buffer_printf(&answer, "\"unsupported\":\"moving scenes are off (--no-motion)\"");
        } else {
            switch (draw_request(request, &opt, &body, why, sizeof why)) {
            case DRAWN: buffer_printf(&answer, "%s", body.text); break;
            case UNSUPPORTED:
                buffer_printf(&answer, "\"unsupported\":");
                buffer_json_string(&answer, why);
                break;
            case FAILED:
                buffer_printf(&answer, "\"error\":");
                buffer_json_string(&answer, why);
                break;
            }
        }
        buffer_printf(&answer, "}\n");
        json_free(request);
        if (answer.failed) {
            fputs("{\"error\":\"out of memory\"}\n", stdout);
        } else {
            fwrite(answer.text, 1, answer.length, stdout);
        }
        fflush(stdout);
    }
    free(line);
    buffer_free(&answer);
    buffer_free(&body);
    return 0;
}
