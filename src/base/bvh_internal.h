/* What the BVH code in memory (src/base/bvh.c) shares with the BVH writer. */
#ifndef SK_BVH_INTERNAL_H
#define SK_BVH_INTERNAL_H

/* The index (0..5) of a channel code of sk_bvh.channel in the order x y z X Y Z, which is
 * the order of the channel names the writer prints, or -1 for any other character. */
int sk__bvh_channel_index(char c);

#endif
