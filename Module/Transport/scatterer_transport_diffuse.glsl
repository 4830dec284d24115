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
// Discretised on the coarse grid with spacing h_a along axis a (finite volumes: what
// leaves a texel through a face enters its neighbour) and solved by Jacobi iteration:
//   phi(x) = (S(x) + sum_f D_f phi(x + f) / h_f^2)
//            / (sum_f D_f / h_f^2 + sigma_a + escape(x))
// over the six faces f. Toward a texel of medium, D_f is the harmonic mean of the two
// texels' D, 2 D D' / (D + D'): the current through two half texels in series, each of
// its own medium. With each texel's own D on all its faces (until 2026-12-07) the current
// across a face between skin and bone differed as seen from either side, so light was
// made or lost there; the harmonic faces brought the CT head's default closer to the
// Monte Carlo reference (docs/model.md, "Multiple scattering").
// Where there is no medium the light escapes (phi = 0), as it does past the grid. Through
// a face toward such a texel the difference quotient with the texel's own D lets out
// D phi / h_a^2 a unit volume, the current D phi / h_a over the face; but at a free
// surface the current leaving is phi / 2 (Marshak's vacuum boundary condition: no light
// comes back in; Ishimaru, ch. 9), and in dense matter (D = 1 / (3 sigma_t) << h_a)
// D phi / h_a is far less: a channel that absorbs nothing (albedo 1) piled its light up
// and glowed (docs/hard-cases.md). So each such face adds what it lacks,
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
uniform sampler2D st_previous;     // coarse grid's atlas: rgb phi of the last iteration, a sigma_t
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

// At coarse texel c: rgb phi of the last iteration, a its sigma_t (pass 0d,
// scatterer_transport_fluence_start.glsl); both 0 outside the grid and where there is no
// medium (the atlas holds 0 there), phi 0 before the first iteration.
vec4 st_phiAndExtinction(ivec3 c)
{
  if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(st_coarseDims))))
  {
    return vec4(0.0);
  }
  vec4 v = texelFetch(st_previous, st_atlasTexel(c), 0);
  return st_first != 0 ? vec4(0.0, 0.0, 0.0, v.a) : v;
}

// D_f of the face between a texel of extinction sigmaT and a neighbour of extinction
// sigmaN: the harmonic mean of their D = 1 / (3 sigma_t), 2 / (3 (sigmaT + sigmaN)), where
// the neighbour holds a medium; else the texel's own D (beyond the grid and toward no
// medium: phi is 0 there, and the escape adds what a free surface lets out).
float st_faceDiffusion(float sigmaT, float sigmaN)
{
  return sigmaN > 0.0 ? 2.0 / (3.0 * (sigmaT + sigmaN)) : 1.0 / (3.0 * sigmaT);
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
  vec3 inflow = vec3(0.0); // sum_f D_f phi(x + f) / h_f^2
  float outflow = 0.0;     // sum_f D_f / h_f^2
  for (int a = 0; a < 3; ++a)
  {
    for (int side = -1; side <= 1; side += 2)
    {
      ivec3 n = c;
      n[a] += side;
      vec4 neighbour = st_phiAndExtinction(n);
      float conductance = st_faceDiffusion(medium.a, neighbour.a) / (st_h[a] * st_h[a]);
      inflow += conductance * neighbour.rgb;
      outflow += conductance;
    }
  }
  vec3 sigmaA = medium.a * max(vec3(1.0) - medium.rgb, vec3(st_leastAbsorption));
  vec3 phi = (source.rgb + inflow) / (outflow + sigmaA + vec3(source.a));
  gl_FragData[0] = vec4(phi, 1.0);
}
