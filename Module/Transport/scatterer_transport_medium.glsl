//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 0a: what each fine texel holds that no light changes
// (all layers in one draw). It runs when the medium does (the volume, its transfer
// functions, clipping, cropping, the materials, the grid), not when a light moves:
// an orbit under the headlight or ParaView's light kit moves the lights every frame.
// - output 0 (FineScattering, rgb): the texel's scattering coefficient as the
//   multiple-scattering source takes it (scatterer_transport_source.glsl): the source
//   is the texel's mean of sigma_s A, and the arriving light's texels hold the light
//   entering them, A_in (scatterer_transport_sweep.glsl); over a texel of optical depth
//   2x along the light, A falls as A_in exp(-s), and its mean is
//     A_in (1 - exp(-2x)) / (2x),   x = OcclusionStrength sigma_t(q) h / 2,
//   so the texel holds sigma_s(q) (1 - exp(-2x)) / (2x), sigma_s = sigma_t albedo, h a
//   fine texel's mean size, sigma_s and sigma_t the means over the texel's points (those
//   of output 2); exact for a light along an axis (one across the texel's diagonal
//   crosses up to sqrt(3) h of it). In a dense texel that is sigma_s A_in / (2x): the light the
//   texel's first mean free paths scatter, not sigma_s A at its centre, which vanishes
//   (exp(-x)) and took the multiple scattering out of dense matter.
// - output 1 (FineGather, st_storedGather): which gather the texel takes
//   (scatterer_transport_gather.glsl): -1 outside every material; its material m when
//   no photon of m's templates lands in another material (the photons then need no
//   material look-up: no tint, no rescale); m + 8 (ST_MIXED) when one does. And whether
//   it is a dense interior texel (st_isInterior).
// - output 2 (FineExtinction): the extinction along light paths (st_attenuationAt,
//   sigma_t times OcclusionStrength), the mean over st_meanPoints^3 points spread evenly
//   over the texel: the sweeps take the far half of each step toward the light from it
//   (st_farExtinction, scatterer_transport_sweep_common.glsl). With st_meanPoints 0 (a
//   texel of one voxel) the sweeps take no mean and output 2 has no target; the texel's
//   medium is then that at its centre.
// Outputs 0 and 2 take the same points. Output 0 took the texel's centre alone (as pass
// 0b still takes each fine texel's, CoarseGrid::Subsamples) until 2026-12-07: a surface
// that cut the texels gave those whose centre it missed no source, and along a surface
// that climbs through the texel layers the diffusion's light rose and fell from layer to
// layer (the bands across the CT head's crown, softer since, not gone: docs/model.md,
// "Multiple scattering").
//============================================================================
//VTK::Transport::Common
//VTK::Transport::Materials
//VTK::Transport::StoredGather
in vec2 texCoord;
flat in float st_layer;          // this layer (scatterer_transport_layers_gs.glsl)
uniform float st_fineSize; // a fine texel's mean size, world units
uniform int st_meanPoints; // output 2: points per axis (ExtinctionSampling::MeanPoints)

// The extinction along light paths (st_attenuationAt) over texel j: the mean over n^3
// points spread evenly over it, or at its centre for n = 0.
float st_meanAttenuation(vec3 j, int n)
{
  if (n == 0)
  {
    return st_attenuationAt(st_gridToTexture(j));
  }
  float sum = 0.0;
  for (int k = 0; k < n * n * n; ++k)
  {
    sum += st_attenuationAt(st_gridToTexture(st_texelPoint(j, k, n)));
  }
  return sum / float(n * n * n);
}

// A texel is dense when the light's optical depth across it, its mean extinction times
// h, exceeds st_denseDepth: the light entering it falls below exp(-st_denseDepth) = 0.14
// inside it. A dense texel whose six neighbours are dense too is an interior texel: no
// light reaches it, and no ray sees into it past the dense texels around it. The gather
// weights it down (scatterer_transport_gather.glsl), so that a ray sample on a dense
// surface reads the light of the surface's texels, not a blend with the dark texels
// behind it, which drew the texel layers on every dense surface as terraces. The mean,
// not the centre: a surface in the far half of a texel whose centre is empty leaves
// the next texel dark (the light entering it has crossed the surface) and, by its
// centre, not interior; the blend with it drew the grid's faces on a dense ball.
const float st_denseDepth = 2.0;
bool st_isDense(float meanAttenuation)
{
  return meanAttenuation * st_fineSize > st_denseDepth;
}

bool st_isDense(vec3 j)
{
  return st_isDense(st_meanAttenuation(j, st_meanPoints));
}

// Texel j, of mean extinction `own`, is an interior texel (its neighbours' means are
// taken only when it is dense itself).
bool st_isInterior(vec3 j, float own)
{
  bool interior = st_isDense(own);
  for (int a = 0; a < 3 && interior; ++a)
  {
    vec3 e = vec3(0.0);
    e[a] = 1.0;
    interior = st_isDense(j + e) && st_isDense(j - e);
  }
  return interior;
}

void main()
{
  vec3 j = vec3(floor(texCoord * st_gridDims.xy), st_layer);
  vec3 t = st_gridToTexture(j);
  vec4 medium = vec4(0.0); // rgb sigma_s, a sigma_t
  int n = max(st_meanPoints, 1);
  for (int k = 0; k < n * n * n; ++k)
  {
    vec4 m = st_mediumAt(st_gridToTexture(st_texelPoint(j, k, n)));
    medium += vec4(m.rgb * m.a, m.a);
  }
  medium /= float(n * n * n);
  // The texel's mean light over the light entering it, (1 - exp(-2x)) / (2x): its
  // series below 1e-3 (no 0 / 0).
  float x = 0.5 * st_occlusionScale * medium.a * st_fineSize;
  float meanOfEntering = x < 1.0e-3 ? 1.0 - x : (1.0 - exp(-2.0 * x)) / (2.0 * x);
  int m = st_materialAt(t);
  float gather = -1.0;
  if (m >= 0)
  {
    bool mixed = false;
    if (st_looksAtPhotons())
    {
      for (int k = 0; k < st_kernelCount && !mixed; ++k)
      {
        int mp = st_materialAt(st_gridToTexture(j + st_photon(m, k).xyz));
        mixed = mp >= 0 && mp != m;
      }
    }
    gather = float(m) + (mixed ? float(ST_MIXED) : 0.0);
  }
  // Output 2 from the same points (st_meanAttenuation(j, st_meanPoints)).
  float own = st_occlusionScale * medium.a;
  gl_FragData[0] = vec4(medium.rgb * meanOfEntering, 1.0);
  gl_FragData[1] = vec4(st_storedGather(gather, st_isInterior(j, own)));
  gl_FragData[2] = vec4(st_meanPoints > 0 ? own : 0.0);
}
