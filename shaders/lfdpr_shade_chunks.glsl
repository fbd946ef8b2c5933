// Tile chunks of the visibility pipeline's shading (lfdpr_visibility_splat.comp marks them,
// lfdpr_visibility_shade_list.comp lists them, lfdpr_visibility_shade.comp shades them): LFDPR_SHADE_TILE-square
// tile positions, each over a run of up to LFDPR_VIEW_CHUNK views. The one definition of
// the tile grid, the chunk index and the mask layout for all three.
// Needs lfdpr_bindings.glsl first.

// Tiles per view in x and y.
uvec2 lfdShadeTiles(uvec2 viewSize)
{
    return (viewSize + uvec2(LFDPR_SHADE_TILE - 1)) / uvec2(LFDPR_SHADE_TILE);
}

// A tile chunk: one tile position of the views [firstView, endView).
struct LfdShadeChunk {
    uvec2 tile;
    uint firstView, endView;
};

uint lfdShadeEntryCount(uvec2 tiles, uint viewCount)
{
    return tiles.x * tiles.y * ((viewCount + uint(LFDPR_VIEW_CHUNK) - 1u) / uint(LFDPR_VIEW_CHUNK));
}

// Chunk index of tile `tile` in view chunk `chunk` (views chunk * LFDPR_VIEW_CHUNK on).
uint lfdShadeChunkIndex(uint chunk, uvec2 tile, uvec2 tiles)
{
    return (chunk * tiles.y + tile.y) * tiles.x + tile.x;
}

// First word of the view mask of (group, chunk index) in LFDPR_SSBO_CHUNK_MASKS.
uint lfdChunkMaskWord(uint group, uint chunkIndex, uint entries)
{
    return (group * entries + chunkIndex) * uint(LFDPR_VIEW_MASK_WORDS);
}

// The tile chunk of a chunk index (lfdShadeChunkIndex inverted).
LfdShadeChunk lfdShadeChunk(uint index, uvec2 tiles, uint viewCount)
{
    LfdShadeChunk c;
    c.tile = uvec2(index % tiles.x, (index / tiles.x) % tiles.y);
    c.firstView = index / (tiles.x * tiles.y) * uint(LFDPR_VIEW_CHUNK);
    c.endView = min(c.firstView + uint(LFDPR_VIEW_CHUNK), viewCount);
    return c;
}

// Takes the lowest view set in a chunk's two-word view mask and clears it: the view's
// offset in the chunk (0-63). Loop as `for (uvec2 bits = mask; bits != uvec2(0u);)`, one
// loop over both words - llvmpipe runs a loop body at least once per SIMD row even when
// none of its invocations has an iteration, so a loop per word cost every row a wasted
// pass for a word its pixel had no view in.
uint lfdTakeChunkView(inout uvec2 bits)
{
    uint word = bits.x != 0u ? 0u : 1u;
    uint v = uint(findLSB(bits[word]));
    bits[word] &= bits[word] - 1u;
    return 32u * word + v;
}
