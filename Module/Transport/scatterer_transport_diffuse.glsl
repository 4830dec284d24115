//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 3b: multiple scattering by diffusion (all layers
// in one draw, Jacobi sweeps on a coarse grid of about 4 voxels; after vpt,
// Zbontar & Lesar, which carries multiple scattering by diffusion).
//
// The diffusion approximation of the light scattered more than once, per colour
// channel (Ishimaru; Jensen et al. 2001, Eq. 4):
//   -div(D grad phi) + sigma_a phi = S,   D = 1 / (3 sigma_t),  sigma_a = sigma_t (1 - albedo)
// S is the light scattered once; phi the fluence it becomes.
// Discretised on the coarse grid with spacing h_a along axis a and solved by Jacobi
// iteration (D taken at the texel):
//   phi(x) = (S(x) + D sum_a (phi(x + e_a) + phi(x - e_a)) / h_a^2)
//            / (2 D sum_a 1 / h_a^2 + sigma_a + escape(x))
// Where there is no medium the light escapes (phi = 0), as it does past the grid. Through
// a face toward such a texel the difference quotient lets out D phi / h_a^2 a unit
// volume, the current D phi / h_a over the face; but at a free surface the current
// leaving is phi / 2 (Marshak's vacuum boundary condition: no light comes back in;
// Ishimaru, ch. 9), and in dense matter (D = 1 / (3 sigma_t) << h_a) D phi / h_a is far
// less: a channel that absorbs nothing (albedo 1) piled its light up and glowed
// (docs/hard-cases.md). So each such face adds what it lacks,
//   escape(x) = sum over faces toward no medium of max(0, 1 / (2 h_a) - D / h_a^2),
// which depends on the coarse medium alone: pass 3a takes it once a build and stores it
// in the source's alpha (scatterer_transport_source.glsl).
// The coarse medium comes from pass 0b (scatterer_transport_coarsen.glsl), the
// source from pass 3a (scatterer_transport_source.glsl); the source and the fluence are
// the coarse grid's atlases (scatterer_transport_atlas.glsl).
//============================================================================
//VTK::Transport::Atlas
in vec2 texCoord;
flat in float st_layer;            // this layer (scatterer_transport_tiles_vs.glsl)
uniform sampler3D st_coarseMedium; // coarse grid: rgb albedo, a sigma_t
uniform sampler2D st_coarseSource; // coarse grid's atlas: rgb the light scattered once, a escape(x)
uniform sampler2D st_previous;     // coarse grid's atlas: phi of the last iteration (rgb)
uniform int st_first;              // 1: no previous iteration (phi = 0)
uniform vec3 st_h;                 // coarse texel size along each axis, world units

// Every channel absorbs at least this fraction of what it scatters. A colour of exactly 1
// (white bone, a white label) absorbs nothing, and in matter whose mean free path is far
// below a coarse texel the escape at its faces drains only what reaches them: such a
// texel's fluence grew to S sigma_t h^2 / 2 an iteration, and a dense white ball glowed
// at the display's ceiling (247 of 255, with 0.999 99, stock Phong 97; at TransportScale
// 1 and 2 185 and 121). Real matter absorbs something; 0.1 % keeps the diffusion length
// of such matter within the grid (1 / sqrt(3 sigma_a sigma_t) = 18 mean free paths).
const float st_leastAbsorption = 0.001;

// phi of the last iteration at coarse texel c: 0 outside the grid and where there is no
// medium (the atlas holds 0 there).
vec3 st_phi(ivec3 c)
{
  if (st_first != 0 || any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(st_coarseDims))))
  {
    return vec3(0.0);
  }
  return texelFetch(st_previous, st_atlasTexel(c), 0).rgb;
}

void main()
{
  ivec3 c = ivec3(ivec2(floor(texCoord * st_coarseDims.xy)), int(st_layer));
  vec4 medium = texelFetch(st_coarseMedium, c, 0);
  if (!st_holdsMedium(medium))
  {
    gl_FragData[0] = vec4(0.0);
    return;
  }
  vec4 source = texelFetch(st_coarseSource, st_atlasTexel(c), 0); // rgb S, a escape(x)
  float D = 1.0 / (3.0 * medium.a);
  vec3 inv2 = 1.0 / (st_h * st_h);
  vec3 neighbours = (st_phi(c + ivec3(1, 0, 0)) + st_phi(c - ivec3(1, 0, 0))) * inv2.x +
    (st_phi(c + ivec3(0, 1, 0)) + st_phi(c - ivec3(0, 1, 0))) * inv2.y +
    (st_phi(c + ivec3(0, 0, 1)) + st_phi(c - ivec3(0, 0, 1))) * inv2.z;
  vec3 sigmaA = medium.a * max(vec3(1.0) - medium.rgb, vec3(st_leastAbsorption));
  vec3 phi = (source.rgb + D * neighbours) / (2.0 * D * (inv2.x + inv2.y + inv2.z) + sigmaA + vec3(source.a));
  gl_FragData[0] = vec4(phi, 1.0);
}
