/* Joining raw DEFLATE streams (RFC 1951): a walk over a stream's blocks that decodes its
 * Huffman codes only to skip them (no output), to find where its final block starts and
 * where it ends; clearing that block's final flag and appending an empty stored block
 * (as a zlib sync flush does) lets another stream follow. libdeflate has no flush, so
 * this is how strips compressed by it in parallel become one stream. */
#include "io/deflate_join.h"

#include <stdlib.h>
#include <string.h>

/* Little-endian 64 bits at byte `at`, zeros past the end (which a valid stream never
 * reads: the walk fails when it passes the end). */
static inline uint64_t load64(const uint8_t *data, size_t size, size_t at)
{
    uint64_t v = 0;
    if (at + 8 <= size) {
        for (int i = 0; i < 8; i++) v |= (uint64_t)data[at + i] << (8 * i);
    } else {
        for (size_t i = 0; at + i < size && i < 8; i++) v |= (uint64_t)data[at + i] << (8 * i);
    }
    return v;
}

typedef struct bit_reader {
    const uint8_t *data;
    size_t size, pos, limit; /* pos and limit in bits */
} bit_reader;

/* The next bits from pos (at least 57 valid ones). */
static inline uint64_t peek(const bit_reader *br)
{
    return load64(br->data, br->size, br->pos >> 3) >> (br->pos & 7);
}

static inline unsigned take(bit_reader *br, int n)
{
    unsigned v = (unsigned)(peek(br) & ((1u << n) - 1));
    br->pos += (size_t)n;
    return v;
}

/* A decoding table indexed by the next `bits` bits of the stream: entry = (bits to skip
 * << 9) | symbol, 0 for a bit pattern that is no code. The skip includes the extra bits
 * that follow a length or distance code, whose values the walk does not need. */
#define TABLE_MAX_BITS 15
typedef struct huffman {
    uint16_t *entry; /* 2^TABLE_MAX_BITS entries of storage */
    int bits;
} huffman;

static const uint8_t length_extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                         2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const uint8_t distance_extra[30] = {0, 0, 0, 0, 1, 1, 2,  2,  3,  3,  4,  4,  5,  5,  6,
                                           6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

enum { ALPHABET_LITLEN, ALPHABET_DISTANCE, ALPHABET_CODELEN };

static int extra_bits(int alphabet, int symbol)
{
    if (alphabet == ALPHABET_LITLEN) return symbol >= 257 && symbol <= 285 ? length_extra[symbol - 257] : 0;
    if (alphabet == ALPHABET_DISTANCE) return symbol < 30 ? distance_extra[symbol] : 0;
    return 0;
}

/* Builds the table of a canonical Huffman code from its code lengths (RFC 1951 3.2.2).
 * False for an over-subscribed code; incomplete codes are allowed (a stream may have a
 * single distance code, or none). */
static bool build(huffman *h, const uint8_t *lengths, int n, int alphabet)
{
    int count[TABLE_MAX_BITS + 1] = {0}, max = 0;
    for (int s = 0; s < n; s++) {
        count[lengths[s]]++;
        if (lengths[s] > max) max = lengths[s];
    }
    count[0] = 0;
    int left = 1;
    for (int l = 1; l <= TABLE_MAX_BITS; l++) {
        left = 2 * left - count[l];
        if (left < 0) return false;
    }
    h->bits = max > 0 ? max : 1;
    size_t size = (size_t)1 << h->bits;
    memset(h->entry, 0, size * sizeof h->entry[0]);
    unsigned next[TABLE_MAX_BITS + 2], code = 0;
    for (int l = 1; l <= TABLE_MAX_BITS; l++) {
        code = (code + (unsigned)count[l - 1]) << 1;
        next[l] = code;
    }
    for (int s = 0; s < n; s++) {
        int l = lengths[s];
        if (l == 0) continue;
        unsigned c = next[l]++, reversed = 0;
        for (int b = 0; b < l; b++) reversed |= ((c >> b) & 1u) << (l - 1 - b);
        uint16_t e = (uint16_t)(((l + extra_bits(alphabet, s)) << 9) | s);
        for (size_t i = reversed; i < size; i += (size_t)1 << l) h->entry[i] = e;
    }
    return true;
}

static inline unsigned decode(bit_reader *br, const huffman *h)
{
    unsigned e = h->entry[peek(br) & (((uint64_t)1 << h->bits) - 1)];
    br->pos += e >> 9;
    return e; /* 0: not a code */
}

/* The symbols of one compressed block up to its end-of-block code. */
static bool skip_symbols(bit_reader *br, const huffman *litlen, const huffman *dist)
{
    for (;;) {
        unsigned e = decode(br, litlen);
        if (e == 0 || br->pos > br->limit) return false;
        unsigned symbol = e & 511;
        if (symbol < 256) continue;
        if (symbol == 256) return true;
        if (symbol > 285) return false;
        e = decode(br, dist);
        if (e == 0 || (e & 511) >= 30 || br->pos > br->limit) return false;
    }
}

static bool read_dynamic_codes(bit_reader *br, huffman *litlen, huffman *dist, huffman *codelen)
{
    static const uint8_t order[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
    int hlit = (int)take(br, 5) + 257, hdist = (int)take(br, 5) + 1, hclen = (int)take(br, 4) + 4;
    if (hlit > 286 || hdist > 30) return false;
    uint8_t cl[19] = {0}, lengths[286 + 30];
    for (int i = 0; i < hclen; i++) cl[order[i]] = (uint8_t)take(br, 3);
    if (!build(codelen, cl, 19, ALPHABET_CODELEN)) return false;
    int total = hlit + hdist;
    for (int i = 0; i < total;) {
        unsigned e = decode(br, codelen);
        if (e == 0 || br->pos > br->limit) return false;
        unsigned symbol = e & 511;
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
    uint16_t *storage = malloc(((size_t)2 << TABLE_MAX_BITS) * sizeof(uint16_t) + 128 * sizeof(uint16_t));
    if (!storage) return false;
    huffman litlen = {storage, 0}, dist = {storage + ((size_t)1 << TABLE_MAX_BITS), 0};
    huffman codelen = {storage + ((size_t)2 << TABLE_MAX_BITS), 0};
    bit_reader br = {data, size, 0, size * 8};
    bool ok = true;
    for (;;) {
        size_t header = br.pos;
        unsigned final = take(&br, 1), type = take(&br, 2);
        if (type == 0) {
            br.pos = (br.pos + 7) & ~(size_t)7;
            if (br.pos + 32 > br.limit) { ok = false; break; }
            unsigned len = take(&br, 16), nlen = take(&br, 16);
            if ((len ^ 0xffffu) != nlen) { ok = false; break; }
            br.pos += (size_t)len * 8;
            if (br.pos > br.limit) { ok = false; break; }
        } else if (type == 1 || type == 2) {
            ok = type == 1 ? fixed_codes(&litlen, &dist) : read_dynamic_codes(&br, &litlen, &dist, &codelen);
            if (!ok || !(ok = skip_symbols(&br, &litlen, &dist))) break;
        } else {
            ok = false;
            break;
        }
        if (final) {
            *final_header_bit = header;
            *end_bit = br.pos;
            break;
        }
    }
    free(storage);
    return ok;
}

bool sk__deflate_make_continuable(uint8_t *data, size_t *size)
{
    size_t header, end;
    if (!sk__deflate_stream_end(data, *size, &header, &end) || (end + 7) / 8 != *size) return false;
    data[header >> 3] &= (uint8_t)~(1u << (header & 7)); /* not final any more */
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
