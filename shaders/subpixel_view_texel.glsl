// The view texel a panel subpixel reads (formats/display_profiles.md section 2): the view
// pixel containing its screen position, in exact integer arithmetic. The one GLSL
// definition, included by the EIA pass (eia_construct.comp) and by the direct subpixel
// splat's shading (lfdpr_direct_shade.comp), which must read the same texel as the EIA's
// nearest mode; the CPU's is viewColumnUnder / viewRowUnder (player/display/eia_builder.h).

// floor(a / b) for unsigned a, b > 0 with a < 2^31, exactly: a float quotient (within a
// few ulps of the true one, so off by at most one below 2^24) corrected by one integer
// multiply each way. Why not a / b: integer division has no vector instruction, so
// llvmpipe divides lane by lane (two divisions per subpixel made them the bulk of the
// EIA pass); this is a handful of vector operations.
uint floorDivide(uint a, uint b)
{
    uint q = uint(float(a) / float(b));
    q -= (q * b > a) ? 1u : 0u;
    q += ((q + 1u) * b <= a) ? 1u : 0u;
    return q;
}

// The view texel under subpixel column k on panel row l (0 = top) of a panel of panelSize
// pixels: floor((k + 0.5) / 3W * viewWidth) and the row likewise, without rounding;
// returned as (x, GL row), GL row 0 = bottom.
ivec2 subpixelViewTexel(uint k, uint l, uvec2 panelSize, uvec2 viewSize)
{
    const uint x = floorDivide((2u * k + 1u) * viewSize.x, 6u * panelSize.x);
    const uint rowFromTop = floorDivide((2u * l + 1u) * viewSize.y, 2u * panelSize.y);
    return ivec2(int(x), int(viewSize.y - 1u - rowFromTop));
}
