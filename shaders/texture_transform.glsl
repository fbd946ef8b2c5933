// KHR_texture_transform's effect on a normal map's tangent frame, shared by
// material_shading.glsl (mvr, lfdpr) and lfdpr_paper_points.frag: the transform turns and
// scales the texture's axes, and the frame follows them as the baker would generate it for
// uvs transformed by hand (gltf_accessors.cpp generateTangents): T' = dP/du' made
// orthogonal to n, B' = cross(n, T') with the handedness of -dP/dv' (glTF's tangent-space
// +Y is up the image, -v; T = dP/du and B = -dP/dv on the way in), where
// [dP/du' dP/dv'] = [dP/du dP/dv] L^-1 by the chain rule (uv = L^-1 (uv' - offset)).
// `uvFromTexcoord` is the slot's linear part L; n, t, b unit, t and b orthogonal to n.
void lfdTransformTangentFrame(mat2 uvFromTexcoord, vec3 n, inout vec3 t, inout vec3 b)
{
    mat2 inv = inverse(uvFromTexcoord);
    vec3 du = t * inv[0][0] - b * inv[0][1];
    vec3 dv = t * inv[1][0] - b * inv[1][1];
    t = normalize(du - n * dot(n, du));
    b = cross(n, t) * (dot(cross(n, t), -dv) < 0.0 ? -1.0 : 1.0);
}
