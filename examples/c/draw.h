/* One request drawn into one answer, for the C example rasterizer: reads
 * the scene (SPEC.md §12.1), walks each primitive's pixels and samples,
 * and writes the fragments each covers (§12.2), moving ones at their
 * instants (§12.8). */
#ifndef DRAW_H
#define DRAW_H

#include <stddef.h>

#include "buffer.h"
#include "json.h"

typedef struct {
    int wrong_tie; /* --wrong-tie: use the opposite tie rule (a planted bug) */
    int ignore_offset; /* --ignore-offset, --no-offset: draw no polygon offset */
    int claim_offset;  /* --ignore-offset: and declare it all the same (a planted bug) */
    int fixed_clip;    /* --fixed-clip: clip-then-snap on all six planes, whatever the case says */
} options;

enum outcome { DRAWN, UNSUPPORTED, FAILED };

/* On DRAWN, `out` holds `"primitives": [...]`; otherwise `why` says what
 * the scene asks that this program does not do, or what was wrong with
 * the request (naming its JSON path). */
enum outcome draw_request(const json *request, const options *o, buffer *out, char *why,
                          size_t why_size);

#endif
