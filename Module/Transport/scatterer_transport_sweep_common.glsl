//============================================================================
// Light transport volume: what the sweeps of pass 1 share (the slice by slice sweep,
// scatterer_transport_sweep.glsl, and a directional light's lines swept in parallel,
// scatterer_transport_lines.glsl and scatterer_transport_line_texels.glsl): the step
// toward the light, the optical depth over it, a slice's shift, and the depth in
// front of a piece of a distributed volume. The sweep's conventions and equations are
// at the top of scatterer_transport_sweep.glsl.
//============================================================================
uniform float st_sliceOrigin;      // the global index of slice 0 (grid texels)
uniform vec3 st_sweepDims;         // (rows, columns, slices) of the sweep texture
uniform mat3 st_worldToGrid;       // world vector -> grid-index vector
uniform mat3 st_gridToWorld;       // grid-index vector -> world vector
uniform int st_stepSamples;        // extinction samples a step (ExtinctionSampling)
uniform sampler3D st_fineExtinction; // per texel its mean extinction (pass 0a); border 0
// Grid position -> st_fineExtinction's texture coordinate, j * scale + offset: the
// texture covers this grid, or (the dim lights' grid, twice as coarse) the fine grid.
uniform vec3 st_gridToMeansScale;
uniform vec3 st_gridToMeansOffset;
// Where a step's far half reads the means, in steps from q back toward the texel the
// step leaves: 0, at q (a texel's own mean stands for its far half), or 1/4 on the dim
// lights' grid (the middle of the far half, among the fine texels it crosses).
uniform float st_farMeanShift;
uniform mat4 st_texToIndex;        // volume texture coordinates -> structured index
uniform sampler2D st_enteringDepth;
uniform vec3 st_enteringLight;     // positional: the light (index space)
uniform vec3 st_enteringU;         // directional: the map plane's basis (index space)
uniform vec3 st_enteringV;
uniform vec2 st_enteringLo;        // directional: the map's corner on the plane
uniform float st_enteringSide;     // directional: the map's side (index units)

// A directional light's step toward it, one slice: in sweep texels (z = +-1), in grid
// texels, and its length in the world; taken once per light on the CPU by the rule
// below (StepTowardLight, ScattererTransportGrid.h), not by every fragment.
uniform vec3 st_stepSweep;
uniform vec3 st_stepGrid;
uniform float st_stepLength;

// One slice toward the light, in the direction `toward` (world): the step in sweep
// texels (z = +-1), in grid texels, and its length in the world. A light nearly in a
// slice's plane would shift sideways without bound: at most 4 texels per step. A
// positional light's sweep takes it per texel (its direction changes from texel to
// texel); StepTowardLight mirrors it for a directional light.
// How many steps the way ds (sweep texels) takes: one a slice, or one per 4 texels
// sideways where the way runs flatter (the cap).
float st_stepsAlong(vec3 ds)
{
  return max(abs(ds.z), length(ds.xy) / 4.0);
}

void st_stepTowardLight(vec3 toward, out vec3 stepSweep, out vec3 stepGrid, out float len)
{
  vec3 ds = st_toSweep * (st_worldToGrid * toward);
  float along = st_stepsAlong(ds);
  stepSweep = ds / max(along, 1.0e-20);
  stepSweep.z = sign(ds.z);
  stepGrid = transpose(st_toSweep) * stepSweep;
  len = length(st_gridToWorld * stepGrid);
}

// A directional light's lines (scatterer_transport_lines.glsl) keep only the slices
// their texels' draw (scatterer_transport_line_texels.glsl) has yet to read: st_lineSlots
// of them, a ring, slice z in layer z mod st_lineSlots. The texels' draw follows every
// few draws of the lines (kTexelSlices, ScattererTransportLightPasses.cxx), so the ring
// holds their slices and the slice before them, not the whole sweep (RG16F, 4 bytes a
// transport voxel).
uniform int st_lineSlots;
int st_lineSlot(float z)
{
  return int(z) % st_lineSlots;
}

// A directional light's lines through slice z: z a, their sideways offset there (z the
// global slice index, a the sideways step per slice, stepSweep.xy * stepSweep.z), and
// round(z a), the whole texels slice z's light is shifted by (the lines' texels).
vec2 st_sliceOffset(float z, vec2 a)
{
  return vec2(z + st_sliceOrigin) * a;
}

vec2 st_sliceTexels(vec2 za)
{
  return floor(za + 0.5);
}

// The shift of slice z, e(z) = round(z a) - z a.
vec2 st_sliceShift(float z, vec2 a)
{
  vec2 za = st_sliceOffset(z, a);
  return st_sliceTexels(za) - za;
}

// The optical depth of the step from grid position j toward the light, in two halves:
// the near half inside the texel (from j to the texel's face toward the light) and the
// far half (from that face to q = j + stepGrid, in the texel before). With S =
// st_stepSamples points f_i = (i + 1/2) / S along the step (ExtinctionSampling: one a
// volume voxel),
//   tau_near = len / S * sum_{f_i <= 1/2} w_i sigma(j + f_i stepGrid)
//              (w_i = 1/2 on the face, else 1)
//   tau_far  = len / 2 * sigmaBar(j + stepGrid)
// (S = 1: below). sigma the extinction along light paths in the volume
// (st_attenuationAt), sigmaBar its mean over a texel (pass 0a, st_fineExtinction, read
// trilinearly between texels; 0 outside the grid). The near half keeps the volume's
// resolution: it decides how much of the light entering the texel passes its centre on.
// The far half, what the light crosses before it enters the texel, is in the texel
// before; there that texel stands for all of its matter rather than for points of one
// line through it, at one read of a one-channel texture instead of a volume read and a
// table read a point. Against the Monte Carlo reference the defaults of all three
// benchmark scenes moved closer, and a light kit's sweeps took about 5 % less time
// (docs/model.md, the sweep). With S = 1 (a texel of one voxel) no texel mean is held (it
// would add a read, and it moved the finest setting of the point-lit scene away, 0.0029
// to 0.0033); each half takes one sample, at f = 1/4 and 3/4, inside the texel's voxel
// and the one before. One sample on the face served both halves until 2026-12-06, but
// there nearest interpolation (vtkVolumeProperty's default) takes either voxel as the
// rounding of the texture coordinate falls: rings across lit dense faces
// (TransportVolume.DenseFaceAtScaleOneShowsNoRings).
//
// A directional light's lines step along their own path (the line's point in each
// slice, off the texel's centre by the slice's shift: scatterer_transport_sweep.glsl),
// and keep at each point p, beside T(p), st_farFactor(p): the light at p reaches the
// face of the texel one step farther from the light times that factor. The light
// entering a texel is then T(q) st_farFactor(q), both interpolated between the lines at
// its q, in one read.
float st_nearHalfDepth(vec3 j, vec3 stepGrid, float len)
{
  if (st_stepSamples == 1)
  {
    return 0.5 * len * st_attenuationAt(st_gridToTexture(j + stepGrid * 0.25));
  }
  float tau = 0.0;
  for (int i = 0; 2 * i + 1 <= st_stepSamples; ++i)
  {
    float f = (float(i) + 0.5) / float(st_stepSamples);
    float a = st_attenuationAt(st_gridToTexture(j + stepGrid * f));
    tau += f < 0.5 ? a : 0.5 * a; // a sample on the face (odd S): half
  }
  return tau * len / float(st_stepSamples);
}

// The far half of the step that reaches grid position q (from j = q - stepGrid): its
// extinction, tau_far = len / 2 * st_farExtinction(q), and its factor, exp(-tau_far).
float st_farExtinction(vec3 q, vec3 stepGrid)
{
  if (st_stepSamples == 1)
  {
    return st_attenuationAt(st_gridToTexture(q - stepGrid * 0.25));
  }
  vec3 m = q - stepGrid * st_farMeanShift;
  return texture(st_fineExtinction, m * st_gridToMeansScale + st_gridToMeansOffset).r;
}

float st_farFactor(vec3 q, vec3 stepGrid, float len)
{
  return exp(-0.5 * len * st_farExtinction(q, stepGrid));
}

// The mean extinction over the far part of a positional light's step from grid position
// j, pathStep (one slice toward the light, along the path), beyond the fraction `near` of
// it: the texels' means of the slice toward the light (st_farExtinction), one a texel
// of the part's sideways course, the last at the step's end q. A swept texel's far half
// takes the mean at q alone (a step at most 4 texels sideways, its far half 2); a marched
// one's runs farther where its path is flat, and a mean at q alone left out what stands
// between (TransportVolume.PointLightOverAPlateLeavesAWallsShadowOnItAlongFlatPaths).
// Kept on that slice: between slices the texels' means put a surface's matter into the
// empty texels above it (TransportVolume.APointLightJustAboveASurfaceLightsIt).
float st_farMeanExtinction(vec3 j, vec3 pathStep, float near)
{
  vec3 stepSweep = st_toSweep * pathStep;
  float slice = (st_toSweep * (j + pathStep)).z;
  int n = clamp(int(ceil((1.0 - near) * length(stepSweep.xy) - 1.0e-3)), 1, 4096);
  float sum = 0.0;
  for (int i = 1; i <= n; ++i)
  {
    vec3 p = st_toSweep * (j + pathStep * (near + (1.0 - near) * float(i) / float(n)));
    p.z = slice;
    sum += st_farExtinction(transpose(st_toSweep) * p, pathStep);
  }
  return sum / float(n);
}

// The extinction at grid position g for a path marched through the grid: the volume itself
// at that point, as the ray caster samples it; 0 outside the grid (no matter there). Not
// the texels' means (until 2026-12-07): interpolated between texels, they put a dense
// plate's extinction into the empty texels above it, whose paths to a point light a few
// voxels up then read T 0.01-0.2 instead of 1, and the plate under the light came out
// black (docs/hard-cases.md).
float st_extinctionAtGrid(vec3 g)
{
  if (any(lessThan(g, vec3(-0.5))) || any(greaterThan(g, st_gridDims - vec3(0.5))))
  {
    return 0.0;
  }
  return st_attenuationAt(st_gridToTexture(g));
}

// The optical depth from grid position j to a positional light along the way from
// fraction `from` of toLight (the grid vector from j to the light) on: marched straight,
// st_stepSamples samples a texel (one a volume voxel),
//   tau = len / n * sum_i sigma(j + (f + (i + 1/2) (e - f) / n) toLight)
// f = from, e the fraction of the way at which the path leaves the grid (1 if the light
// is inside: beyond the grid there is no matter), n = ceil((e - f) max|toLight|
// st_stepSamples) (at least 1), len the world length of toLight.
// For texels whose path to the light no slice before holds (scatterer_transport_sweep.glsl).
float st_depthToLight(vec3 j, vec3 toLight, float from)
{
  float reach = max(max(abs(toLight.x), abs(toLight.y)), abs(toLight.z));
  float end = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    if (abs(toLight[a]) > 1.0e-6)
    {
      float bound = toLight[a] > 0.0 ? st_gridDims[a] - 0.5 : -0.5;
      end = min(end, (bound - j[a]) / toLight[a]);
    }
  }
  if (end <= from)
  {
    return 0.0;
  }
  int n = clamp(int(ceil((end - from) * reach * float(st_stepSamples))), 1, 4096);
  float segment = (end - from) / float(n);
  float tau = 0.0;
  for (int i = 0; i < n; ++i)
  {
    tau += st_extinctionAtGrid(j + toLight * (from + (float(i) + 0.5) * segment));
  }
  return tau * length(st_gridToWorld * toLight) * segment;
}

// The first fraction `to` of that way, from texel j's centre: one sample halfway.
float st_nearDepthToLight(vec3 j, vec3 toLight, float to)
{
  return st_extinctionAtGrid(j + toLight * (0.5 * to)) * length(st_gridToWorld * toLight) * to;
}

// A directional light's light entering the texel at grid position j, T(q) exp(-tau_far),
// from what its lines keep at q: (T, st_farFactor) interpolated between the lines'
// points. With one extinction sample a step (ST_SWEEP_ONE_SAMPLE: TransportScale 1) the
// far half is one point of the volume as its interpolation gives it (nearest by default:
// a voxel's value up to its face), and interpolated between lines that factor spreads a
// voxel's face over a texel: a seam of light along the side of a dense plate
// (`dense-ball` at the finest setting). There it is taken along the texel's own segment
// (a volume read more a texel).
float st_lightEnteringTexel(vec2 keptAtQ, vec3 j)
{
#if ST_SWEEP_ONE_SAMPLE
  return keptAtQ.r * st_farFactor(j + st_stepGrid, st_stepGrid, st_stepLength);
#else
  return keptAtQ.r * keptAtQ.g;
#endif
}

// The program comes in one variant per kind of light (ScattererTransportPrograms.cxx):
// ST_SWEEP_ENTERING, the depth in front of a piece: 0 none, 1 a directional map, 2 a
// positional (octahedral) one. Mirrors scatterer::lightspace::Map::coordinate.
vec2 st_octahedral(vec3 d)
{
  vec2 p = d.xy / (abs(d.x) + abs(d.y) + abs(d.z));
  if (d.z < 0.0)
  {
    vec2 s = vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
    p = (vec2(1.0) - abs(p.yx)) * s;
  }
  return p;
}

// The optical depth in front of this piece on the light's line through index i.
float st_depthInFront(vec3 i)
{
#if ST_SWEEP_ENTERING == 0
  return 0.0;
#else
#if ST_SWEEP_ENTERING == 2
  vec3 d = i - st_enteringLight;
  vec2 c = st_octahedral(length(d) > 0.0 ? normalize(d) : vec3(0.0, 0.0, 1.0)) * 0.5 + vec2(0.5);
#else
  vec2 c = (vec2(dot(i, st_enteringU), dot(i, st_enteringV)) - st_enteringLo) / st_enteringSide;
#endif
  return texture(st_enteringDepth, c).r;
#endif
}

// What the transmittance texture holds for the texel of grid position j: the light
// entering it, times the light the pieces in front of it leave.
float st_storedTransmittance(float Tentering, vec3 j)
{
  vec3 index = (st_texToIndex * vec4(st_gridToTexture(j), 1.0)).xyz;
  return Tentering * exp(-st_depthInFront(index));
}
