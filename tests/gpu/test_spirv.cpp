// The exact shaders use only operations Vulkan requires to be correctly rounded, so their bits do
// not depend on the driver: checked on the embedded SPIR-V itself. The step shader is first
// specialized to its exact variant (fast-math constant frozen to false, dead branches removed, as
// the driver would), then disassembled:
//  - no OpFDiv / OpFRem / OpFMod, no GLSL.std.450 Sqrt, InverseSqrt, Fma, Exp, Pow, Length,
//    Normalize, Distance;
//  - every floating-point add, sub, mul, negate, vector*scalar and dot is decorated NoContraction;
//  - SignedZeroInfNanPreserve is declared for 32-bit floats.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "gpu/shaders.h"
#include "shared/water_gpu.h"

namespace pond::test {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Disassembly of `spirv`, optionally specialized: fast-math constant = `fast`, frozen, inlined and
// dead code removed.
std::string disassemble(std::span<const std::uint32_t> spirv, const std::string& tag, bool specialize, bool fast) {
  const std::string dir = POND_TEST_TMP_DIR;
  const std::string in = dir + "/" + tag + ".spv", opt = dir + "/" + tag + ".opt.spv", txt = dir + "/" + tag + ".txt";
  {
    std::ofstream f(in, std::ios::binary);
    f.write(reinterpret_cast<const char*>(spirv.data()), static_cast<std::streamsize>(spirv.size_bytes()));
  }
  std::string source = in;
  if (specialize) {
    const std::string cmd = std::string(POND_SPIRV_OPT) + " --set-spec-const-default-value \"" +
                            std::to_string(POND_SPEC_FAST_MATH) + ":" + (fast ? "true" : "false") +
                            "\" --freeze-spec-const --inline-entry-points-exhaustive --eliminate-dead-branches "
                            "--eliminate-dead-functions --eliminate-dead-code-aggressive " + in + " -o " + opt;
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    source = opt;
  }
  const std::string dis = std::string(POND_SPIRV_DIS) + " " + source + " -o " + txt;
  EXPECT_EQ(std::system(dis.c_str()), 0) << dis;
  return read_text(txt);
}

struct Findings {
  std::set<std::string> forbidden;   // forbidden instructions seen
  std::set<std::string> contracted;  // arithmetic result ids without NoContraction
  int arithmetic = 0;
  bool signed_zero_preserve = false;
};

Findings inspect(const std::string& text) {
  Findings f;
  std::set<std::string> no_contraction;
  static const std::regex decoration(R"(OpDecorate (%\S+) NoContraction)");
  for (std::sregex_iterator it(text.begin(), text.end(), decoration), end; it != end; ++it)
    no_contraction.insert((*it)[1]);
  static const std::regex arith(R"((%\S+) = (OpFAdd|OpFSub|OpFMul|OpFNegate|OpVectorTimesScalar|OpDot) )");
  for (std::sregex_iterator it(text.begin(), text.end(), arith), end; it != end; ++it) {
    ++f.arithmetic;
    if (!no_contraction.count((*it)[1])) f.contracted.insert((*it)[1].str() + " " + (*it)[2].str());
  }
  static const std::regex bad(R"(= (OpFDiv|OpFRem|OpFMod) |OpExtInst %\S+ %\S+ (Sqrt|InverseSqrt|Fma|Exp|Exp2|Pow|Length|Normalize|Distance)\b)");
  for (std::sregex_iterator it(text.begin(), text.end(), bad), end; it != end; ++it)
    f.forbidden.insert((*it)[1].matched ? (*it)[1].str() : (*it)[2].str());
  f.signed_zero_preserve = text.find("SignedZeroInfNanPreserve 32") != std::string::npos;
  return f;
}

void expect_exact(const Findings& f, const char* what) {
  EXPECT_TRUE(f.forbidden.empty()) << what << " uses " << *f.forbidden.begin();
  EXPECT_TRUE(f.contracted.empty()) << what << ": " << f.contracted.size() << " arithmetic results may be contracted, e.g. "
                                    << *f.contracted.begin();
  EXPECT_GT(f.arithmetic, 20) << what << ": the inspection found no arithmetic (wrong module?)";
  EXPECT_TRUE(f.signed_zero_preserve) << what << " does not declare SignedZeroInfNanPreserve";
}

TEST(SpirvTest, ExactStepUsesOnlyCorrectlyRoundedUncontractedOps) {
  for (const bool int64 : {false, true})
    for (const bool denorm : {false, true}) {
      const std::string name = std::string("water_step_exact") + (int64 ? "_int64" : "") + (denorm ? "_denorm" : "");
      const std::string text = disassemble(gpu::water_step_spirv(int64, denorm), name.c_str(), true, false);
      expect_exact(inspect(text), name.c_str());
      EXPECT_EQ(text.find("DenormPreserve 32") != std::string::npos, denorm) << name;
    }
}

TEST(SpirvTest, FastStepReallyUsesHardwareInverseSqrt) {
  // The check above is meaningful only if specialization really selects the variants.
  const Findings f = inspect(disassemble(gpu::water_step_spirv(false, false), "water_step_fast", true, true));
  EXPECT_TRUE(f.forbidden.count("InverseSqrt"));
}

TEST(SpirvTest, PerturbAndNormalsAreExact) {
  for (const bool denorm : {false, true}) {
    const Findings perturb = inspect(disassemble(gpu::water_perturb_spirv(denorm), "water_perturb", false, false));
    EXPECT_TRUE(perturb.forbidden.empty());
    EXPECT_TRUE(perturb.contracted.empty());
    EXPECT_TRUE(perturb.signed_zero_preserve);
    expect_exact(inspect(disassemble(gpu::water_normals_spirv(denorm), "water_normals", false, false)), "water_normals");
  }
}

// The tile bounds' shaders (gpu/tile_kernels.h): the normals' variant as exact as the normals; the
// merge only compares and selects, with NaN compares kept (SignedZeroInfNanPreserve).
TEST(SpirvTest, TileBoundsShadersAreExact) {
  for (const bool denorm : {false, true}) {
    const std::string text = disassemble(gpu::water_normals_tiles_spirv(denorm), "water_normals_tiles", false, false);
    expect_exact(inspect(text), "water_normals_tiles");
    EXPECT_NE(text.find("TileColumns"), std::string::npos) << "not the tile variant";
    const Findings tiles = inspect(disassemble(gpu::water_tiles_spirv(denorm), "water_tiles", false, false));
    EXPECT_TRUE(tiles.forbidden.empty());
    EXPECT_TRUE(tiles.contracted.empty());
    EXPECT_TRUE(tiles.signed_zero_preserve);
  }
}

}  // namespace
}  // namespace pond::test
