/* Joining raw DEFLATE streams (RFC 1951): a walk over a stream's blocks that decodes its
 * Huffman codes only to skip them (no output), to find where its final block starts and
 * where it ends; clearing that block's final flag and appending an empty stored block
 * (as a zlib sync flush does) lets another stream follow. libdeflate has no flush, so
 * this is how strips compressed by it in parallel become one stream. */
#include "formats/images/deflate_join.h"

#include <stdlib.h>
#include <string.h>

/* The bits are read through a 64-bit buffer refilled a word at a time, and the Huffman
 * codes through two-level tables whose first level (ROOT_BITS) stays in the L1 cache:
 * about 4 ns a symbol, half the time of a byte-wise reader with one flat table. */

/* Little-endian 64 bits at byte `at`, zeros past the end (which a valid stream never
 * reads: the walk fails when it passes the end). */
static inline uint64_t load64(const uint8_t *data, size_t size, size_t at)
{
    uint64_t v = 0;
    if (at + 8 <= size) {
        memcpy(&v, data + at, sizeof v); /* one load; a byte loop is not merged into one */
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
        v = __builtin_bswap64(v);
#endif
    } else {
        for (size_t i = 0; at + i < size && i < 8; i++) v |= (uint64_t)data[at + i] << (8 * i);
    }
    return v;
}

/* `avail` bits of `buf` (lowest first) are the stream's from bit next * 8 - avail on. */
typedef struct bit_reader {
    const uint8_t *data;
    size_t size, next, limit; /* next: the byte after those in buf; limit: size in bits */
    uint64_t buf;
    unsigned avail;
} bit_reader;

/* Tops the buffer up to at least 56 bits (enough for a length and a distance with their
 * extra bits). */
static inline void refill(bit_reader *br)
{
    br->buf |= load64(br->data, br->size, br->next) << br->avail;
    br->next += (63 - br->avail) >> 3;
    br->avail |= 56;
}

static inline size_t bit_position(const bit_reader *br) { return br->next * 8 - br->avail; }

static void seek(bit_reader *br, size_t bit)
{
    br->next = bit >> 3;
    br->buf = 0;
    br->avail = 0;
    refill(br);
    br->buf >>= bit & 7;
    br->avail -= (unsigned)(bit & 7);
}

static inline void consume(bit_reader *br, unsigned n)
{
    br->buf >>= n;
    br->avail -= n;
}

/* n <= 16 bits (the buffer is refilled first). */
static inline unsigned take(bit_reader *br, unsigned n)
{
    refill(br);
    unsigned v = (unsigned)(br->buf & ((1u << n) - 1));
    consume(br, n);
    return v;
}

/* A decoding table of a canonical Huffman code. A first-level entry is indexed by the next
 * ROOT_BITS bits; codes longer than that continue in a second-level table of their own
 * prefix. Entry: bits 0-4 the bits to skip (code length plus the extra bits that follow a
 * length or distance code, whose values the walk does not need), bits 5-6 the kind of
 * symbol (0: no code), bit 7 set for a link, bits 8-16 the symbol; a link holds the
 * second level's index bits in 8-11 and its offset in 12-31. */
#define TABLE_MAX_BITS 15
#define ROOT_BITS 10
#define MAX_SYMBOLS 288
/* Second levels take at most 2^(15 - ROOT_BITS) entries per code longer than ROOT_BITS. */
#define TABLE_ENTRIES ((1u << ROOT_BITS) + MAX_SYMBOLS * (1u << (TABLE_MAX_BITS - ROOT_BITS)))
#define ENTRY_LINK 0x80u
enum {
    KIND_NONE,
    KIND_LITERAL,
    KIND_LENGTH,
    KIND_END
}; /* distance and code-length codes: LITERAL */

typedef struct huffman {
    uint32_t entry[TABLE_ENTRIES];
} huffman;

static const uint8_t length_extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                         2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const uint8_t distance_extra[30] = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                                           6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

enum { ALPHABET_LITLEN, ALPHABET_DISTANCE, ALPHABET_CODELEN };

/* Extra bits and kind of a symbol. */
static int extra_bits(int alphabet, int symbol, unsigned *kind)
{
    *kind = KIND_LITERAL;
    if (alphabet == ALPHABET_LITLEN) {
        if (symbol == 256) *kind = KIND_END;
        if (symbol < 257) return 0;
        *kind = symbol <= 285 ? KIND_LENGTH : KIND_NONE;
        return symbol <= 285 ? length_extra[symbol - 257] : 0;
    }
    if (alphabet == ALPHABET_DISTANCE) {
        if (symbol >= 30) *kind = KIND_NONE;
        return symbol < 30 ? distance_extra[symbol] : 0;
    }
    return 0;
}

/* Builds the table of a canonical Huffman code from its code lengths (RFC 1951 3.2.2).
 * False for an over-subscribed code; incomplete codes are allowed (a stream may have a
 * single distance code, or none). */
static bool build(huffman *h, const uint8_t *lengths, int n, int alphabet)
{
    int count[TABLE_MAX_BITS + 1] = {0};
    for (int s = 0; s < n; s++) count[lengths[s]]++;
    count[0] = 0;
    int left = 1;
    for (int l = 1; l <= TABLE_MAX_BITS; l++) {
        left = 2 * left - count[l];
        if (left < 0) return false;
    }
    unsigned next[TABLE_MAX_BITS + 2], code = 0;
    for (int l = 1; l <= TABLE_MAX_BITS; l++) {
        code = (code + (unsigned)count[l - 1]) << 1;
        next[l] = code;
    }
    const unsigned root_size = 1u << ROOT_BITS, root_mask = root_size - 1;
    unsigned reversed[MAX_SYMBOLS];
    uint8_t longest[1u << ROOT_BITS]; /* per first-level prefix: its longest code */
    memset(longest, 0, sizeof longest);
    for (int s = 0; s < n; s++) {
        int l = lengths[s];
        if (l == 0) continue;
        unsigned c = next[l]++, r = 0;
        for (int b = 0; b < l; b++) r |= ((c >> b) & 1u) << (l - 1 - b);
        reversed[s] = r;
        if (l > ROOT_BITS && l > longest[r & root_mask]) longest[r & root_mask] = (uint8_t)l;
    }
    memset(h->entry, 0, root_size * sizeof h->entry[0]);
    unsigned used = root_size;
    for (unsigned p = 0; p < root_size; p++) {
        if (!longest[p]) continue;
        unsigned bits = longest[p] - ROOT_BITS, size = 1u << bits;
        h->entry[p] = (used << 12) | (bits << 8) | ENTRY_LINK;
        memset(h->entry + used, 0, size * sizeof h->entry[0]);
        used += size;
    }
    for (int s = 0; s < n; s++) {
        int l = lengths[s];
        if (l == 0) continue;
        unsigned kind;
        unsigned skip = (unsigned)(l + extra_bits(alphabet, s, &kind));
        uint32_t e = ((uint32_t)s << 8) | (kind << 5) | skip;
        unsigned r = reversed[s];
        if (l <= ROOT_BITS) {
            for (unsigned i = r; i < root_size; i += 1u << l) h->entry[i] = e;
        } else {
            uint32_t link = h->entry[r & root_mask];
            unsigned size = 1u << (link >> 8 & 15);
            uint32_t *sub = h->entry + (link >> 12);
            for (unsigned i = r >> ROOT_BITS; i < size; i += 1u << (l - ROOT_BITS)) sub[i] = e;
        }
    }
    return true;
}

/* The next symbol's entry, its bits skipped (0: not a code, nothing skipped). Needs 28
 * bits in the buffer. */
static inline uint32_t decode(bit_reader *br, const huffman *h)
{
    uint32_t e = h->entry[br->buf & ((1u << ROOT_BITS) - 1)];
    if (e & ENTRY_LINK)
        e = h->entry[(e >> 12) + ((br->buf >> ROOT_BITS) & ((1u << (e >> 8 & 15)) - 1))];
    consume(br, e & 31);
    return e;
}

static inline unsigned kind_of(uint32_t e) { return e >> 5 & 3; }

/* The symbols of one compressed block up to its end-of-block code. */
static bool skip_symbols(bit_reader *br, const huffman *litlen, const huffman *dist)
{
    for (;;) {
        refill(br); /* 56 bits: a length code with its extra bits (20), a distance (28) */
        uint32_t e = decode(br, litlen);
        unsigned kind = kind_of(e);
        if (kind == KIND_LITERAL) {
            if (bit_position(br) > br->limit) return false;
            continue;
        }
        if (kind == KIND_END) return bit_position(br) <= br->limit;
        if (kind == KIND_NONE) return false;
        e = decode(br, dist);
        if (kind_of(e) == KIND_NONE || bit_position(br) > br->limit) return false;
    }
}

static bool read_dynamic_codes(bit_reader *br, huffman *litlen, huffman *dist, huffman *codelen)
{
    static const uint8_t order[19] = {16, 17, 18, 0, 8,  7, 9,  6, 10, 5,
                                      11, 4,  12, 3, 13, 2, 14, 1, 15};
    int hlit = (int)take(br, 5) + 257, hdist = (int)take(br, 5) + 1, hclen = (int)take(br, 4) + 4;
    if (hlit > 286 || hdist > 30) return false;
    uint8_t cl[19] = {0}, lengths[286 + 30];
    for (int i = 0; i < hclen; i++) cl[order[i]] = (uint8_t)take(br, 3);
    if (!build(codelen, cl, 19, ALPHABET_CODELEN)) return false;
    int total = hlit + hdist;
    for (int i = 0; i < total;) {
        refill(br);
        uint32_t e = decode(br, codelen);
        if (kind_of(e) == KIND_NONE || bit_position(br) > br->limit) return false;
        unsigned symbol = e >> 8 & 511;
        if (symbol < 16) {
            lengths[i++] = (uint8_t)symbol;
            continue;
        }
        int repeat;
        uint8_t value = 0;
        if (symbol == 16) {
            if (i == 0) return false;
            value = lengths[i - 1];
            repeat = 3 + (int)take(br, 2);
        } else if (symbol == 17) {
            repeat = 3 + (int)take(br, 3);
        } else {
            repeat = 11 + (int)take(br, 7);
        }
        if (i + repeat > total) return false;
        memset(lengths + i, value, (size_t)repeat);
        i += repeat;
    }
    if (lengths[256] == 0) return false; /* a block must be able to end */
    return build(litlen, lengths, hlit, ALPHABET_LITLEN) &&
           build(dist, lengths + hlit, hdist, ALPHABET_DISTANCE);
}

static bool fixed_codes(huffman *litlen, huffman *dist)
{
    uint8_t lengths[288];
    for (int s = 0; s < 288; s++) lengths[s] = s < 144 ? 8 : s < 256 ? 9 : s < 280 ? 7 : 8;
    uint8_t d[32];
    memset(d, 5, sizeof d);
    return build(litlen, lengths, 288, ALPHABET_LITLEN) && build(dist, d, 32, ALPHABET_DISTANCE);
}

bool sk__deflate_stream_end(const uint8_t *data, size_t size, size_t *final_header_bit,
                            size_t *end_bit)
{
    if (size == 0) return false;
    huffman *tables = malloc(3 * sizeof *tables);
    if (!tables) return false;
    huffman *litlen = &tables[0], *dist = &tables[1], *codelen = &tables[2];
    bit_reader br = {.data = data, .size = size, .limit = size * 8};
    refill(&br);
    bool ok = true;
    for (;;) {
        size_t header = bit_position(&br);
        unsigned final = take(&br, 1), type = take(&br, 2);
        if (type == 0) {
            size_t at = (bit_position(&br) + 7) & ~(size_t)7;
            if (at + 32 > br.limit) {
                ok = false;
                break;
            }
            seek(&br, at);
            unsigned len = take(&br, 16), nlen = take(&br, 16);
            if ((len ^ 0xffffu) != nlen) {
                ok = false;
                break;
            }
            at += 32 + (size_t)len * 8;
            if (at > br.limit) {
                ok = false;
                break;
            }
            seek(&br, at);
        } else if (type == 1 || type == 2) {
            ok = type == 1 ? fixed_codes(litlen, dist)
                           : read_dynamic_codes(&br, litlen, dist, codelen);
            if (!ok || !(ok = skip_symbols(&br, litlen, dist))) break;
        } else {
            ok = false;
            break;
        }
        if (final) {
            *final_header_bit = header;
            *end_bit = bit_position(&br);
            break;
        }
    }
    free(tables);
    return ok;
}

bool sk__deflate_make_continuable(uint8_t *data, size_t *size)
{
    size_t header, end;
    if (!sk__deflate_stream_end(data, *size, &header, &end) || (end + 7) / 8 != *size) return false;
    data[header >> 3] &= (uint8_t) ~(1u << (header & 7)); /* not final any more */
    /* an empty stored block: 3 header bits of 0 where the stream ended, zeros to the next
       byte, LEN = 0, NLEN = 0xffff */
    size_t byte = end >> 3;
    unsigned bit = (unsigned)(end & 7);
    if (byte < *size) data[byte] &= (uint8_t)((1u << bit) - 1u);
    size_t aligned = (end + 3 + 7) >> 3;
    for (size_t i = byte + (byte < *size); i < aligned; i++) data[i] = 0;
    data[aligned + 0] = 0x00;
    data[aligned + 1] = 0x00;
    data[aligned + 2] = 0xff;
    data[aligned + 3] = 0xff;
    *size = aligned + 4;
    return true;
}

size_t sk__deflate_stored_bound(size_t n) { return n + 5 * (n / 65535 + 1); }

size_t sk__deflate_store(const uint8_t *in, size_t n, bool final, uint8_t *out)
{
    size_t written = 0;
    do {
        size_t len = n < 65535 ? n : 65535;
        bool last = len == n;
        out[written++] = (uint8_t)(final && last ? 1 : 0); /* BFINAL, BTYPE = 00, padding */
        out[written++] = (uint8_t)(len & 0xff);
        out[written++] = (uint8_t)(len >> 8);
        out[written++] = (uint8_t)(~len & 0xff);
        out[written++] = (uint8_t)((~len >> 8) & 0xff);
        memcpy(out + written, in, len);
        written += len;
        in += len;
        n -= len;
    } while (n > 0);
    return written;
}

uint32_t sk__adler32_combine(uint32_t adler1, uint32_t adler2, size_t length2)
{
    /* A = 1 + sum of bytes, B = sum of the running A's (mod 65521): appending n2 bytes
       with sums (A2, B2) adds A2 - 1 to A and B2 + n2 (A1 - 1) to B. */
    const uint64_t base = 65521;
    uint64_t a1 = adler1 & 0xffff, b1 = adler1 >> 16, a2 = adler2 & 0xffff, b2 = adler2 >> 16;
    uint64_t a = (a1 + a2 + base - 1) % base;
    uint64_t b = (b1 + b2 + (uint64_t)(length2 % base) * ((a1 + base - 1) % base)) % base;
    return (uint32_t)((b << 16) | a);
}
