/* Joining independently compressed raw DEFLATE streams (RFC 1951) into one, so that strips
 * of an image can be compressed in parallel and still form the single zlib stream PNG
 * requires (private to the PNG writer). */
#ifndef SK_IO_DEFLATE_JOIN_H
#define SK_IO_DEFLATE_JOIN_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Walks the blocks of a complete raw DEFLATE stream of `size` bytes (decoding its Huffman
 * codes without producing output): the bit offset of its final block's header and the bit
 * offset where the stream ends. False if the data is not one complete, valid stream. */
bool sk__deflate_stream_end(const uint8_t *data, size_t size, size_t *final_header_bit,
                            size_t *end_bit);

/* Turns the complete raw DEFLATE stream data[0..*size) into one that continues: its final
 * block is marked not final and an empty stored block aligns it to a byte, so that another
 * stream may follow. `data` must have room for 5 more bytes. False (data unchanged) if
 * the stream does not walk (sk__deflate_stream_end). */
bool sk__deflate_make_continuable(uint8_t *data, size_t *size);

/* Stored (uncompressed) DEFLATE blocks holding in[0..n), the last marked final if `final`;
 * writes sk__deflate_stored_bound(n) bytes at most and returns the count. */
size_t sk__deflate_stored_bound(size_t n);
size_t sk__deflate_store(const uint8_t *in, size_t n, bool final, uint8_t *out);

/* The Adler-32 checksum of the concatenation of two byte sequences from theirs, the second
 * `length2` bytes long (RFC 1950). */
uint32_t sk__adler32_combine(uint32_t adler1, uint32_t adler2, size_t length2);

#endif
