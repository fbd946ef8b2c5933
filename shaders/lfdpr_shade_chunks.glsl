// Tile chunks of the visibility pipeline's shading (lfdpr_shade_list.comp, lfdpr_shade.comp):
// LFDPR_SHADE_TILE-square tile positions, each over a run of up to LFDPR_VIEW_CHUNK views.
// Needs lfdpr_bindings.glsl first.

// A tile chunk: one tile position of the views [firstView, endView).
struct LfdShadeChunk {
    uvec2 tile;
    uint firstView, endView;
};

uint lfdShadeEntryCount(uvec2 tiles, uint viewCount)
{
    return tiles.x * tiles.y * ((viewCount + uint(LFDPR_VIEW_CHUNK) - 1u) / uint(LFDPR_VIEW_CHUNK));
}

// Chunk index = (chunk * tiles.y + tile y) * tiles.x + tile x.
LfdShadeChunk lfdShadeChunk(uint index, uvec2 tiles, uint viewCount)
{
    LfdShadeChunk c;
    c.tile = uvec2(index % tiles.x, (index / tiles.x) % tiles.y);
    c.firstView = index / (tiles.x * tiles.y) * uint(LFDPR_VIEW_CHUNK);
    c.endView = min(c.firstView + uint(LFDPR_VIEW_CHUNK), viewCount);
    return c;
}
