// Generation time of the paper's configuration: 4 materials x 8 templates at threshold
// 0.01 (target <= 5 ms), plus one template and the GPU packing step for scale.
#include <scatterer/Pack.h>
#include <scatterer/Template.h>

#include <benchmark/benchmark.h>

#include <string>

using namespace scatterer;

namespace
{

void BM_Generate4Materials8Templates(benchmark::State& state)
{
  const std::vector<Material> materials = exampleTissueMaterials();
  const GeneratorSettings settings; // 4 lights, threshold 0.01, 8 templates
  std::size_t photons = 0;
  for (auto _ : state)
  {
    const auto all = generateAllTemplates(materials, settings);
    benchmark::DoNotOptimize(all.data());
    photons = 0;
    for (const auto& templates : all)
    {
      for (const Template& t : templates)
      {
        photons += t.photons.size();
      }
    }
  }
  // A label, not a counter: Google Benchmark 1.7's CSV writer aborts when benchmarks
  // have different counter sets.
  state.SetLabel("photons=" + std::to_string(photons));
}
BENCHMARK(BM_Generate4Materials8Templates)->Unit(benchmark::kMillisecond);

void BM_GenerateOneTemplateHalfOpacity(benchmark::State& state)
{
  Material m;
  m.opacity = 0.5;
  const GeneratorSettings settings;
  for (auto _ : state)
  {
    Template t = generateTemplate(m, settings, 0);
    benchmark::DoNotOptimize(t.photons.data());
  }
}
BENCHMARK(BM_GenerateOneTemplateHalfOpacity)->Unit(benchmark::kMicrosecond);

void BM_Pack4x8(benchmark::State& state)
{
  const auto all = generateAllTemplates(exampleTissueMaterials(), GeneratorSettings{});
  const auto format = state.range(0) == 16 ? TexelFormat::RGBA16F : TexelFormat::RGBA32F;
  std::size_t bytes = 0;
  for (auto _ : state)
  {
    PackedTemplates p = packTemplates(all, 64, format);
    benchmark::DoNotOptimize(p.rgba.data());
    bytes = p.byteCount();
  }
  state.SetLabel("bytes=" + std::to_string(bytes));
}
BENCHMARK(BM_Pack4x8)->Arg(32)->Arg(16)->Unit(benchmark::kMicrosecond);

} // namespace

BENCHMARK_MAIN();
