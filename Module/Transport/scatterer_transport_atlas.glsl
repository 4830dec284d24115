//============================================================================
// Light transport volume: the diffusion's coarse grid as its source and Jacobi passes
// draw it (3a, 3b), a 2D atlas of its layers: layer z is the tile
// (z % st_atlasColumns, z / st_atlasColumns) of st_coarseDims.xy texels
// (CoarseGrid::AtlasColumns says why: llvmpipe shares a draw among its threads by 2D
// tiles of the framebuffer).
//============================================================================
uniform vec3 st_coarseDims;
uniform int st_atlasColumns;

// Whether a coarse texel of this medium (pass 0b: rgb albedo, a sigma_t) holds one: where
// none, nothing scatters, the diffusion writes no light and its light escapes through the
// faces toward it (scatterer_transport_diffuse.glsl).
bool st_holdsMedium(vec4 coarseMedium)
{
  return coarseMedium.a > 1.0e-6;
}

// The atlas's texel of coarse texel c (inside the grid).
ivec2 st_atlasTexel(ivec3 c)
{
  ivec2 tile = ivec2(c.z % st_atlasColumns, c.z / st_atlasColumns);
  return c.xy + tile * ivec2(st_coarseDims.xy);
}

// The atlas read as a 3D texture of the coarse grid with linear filtering and clamped to
// its edges, at texture coordinate t: between two layers, each read bilinearly inside
// its own tile (the position kept half a texel from the tile's edges, so that no
// neighbouring tile enters).
vec4 st_atlasLinear(sampler2D atlas, vec3 t)
{
  vec3 p = clamp(t * st_coarseDims - vec3(0.5), vec3(0.0), st_coarseDims - vec3(1.0));
  float z0 = floor(p.z);
  float z1 = min(z0 + 1.0, st_coarseDims.z - 1.0);
  vec2 size = vec2(textureSize(atlas, 0));
  vec2 tile0 = vec2(mod(z0, float(st_atlasColumns)), floor(z0 / float(st_atlasColumns)));
  vec2 tile1 = vec2(mod(z1, float(st_atlasColumns)), floor(z1 / float(st_atlasColumns)));
  vec4 a = texture(atlas, (tile0 * st_coarseDims.xy + p.xy + vec2(0.5)) / size);
  vec4 b = texture(atlas, (tile1 * st_coarseDims.xy + p.xy + vec2(0.5)) / size);
  return mix(a, b, p.z - z0);
}
