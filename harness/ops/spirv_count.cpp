#include "harness/ops/spirv_count.h"

#include "harness/ops/spirv_cache.h"
#include "harness/ops/spirv_compile.h"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <vector>

namespace mb::spirv {
namespace {

namespace fs = std::filesystem;

// Shape of a SPIR-V type: scalar (cols 0, comps 1), vector (comps N), matrix (cols C of comps R).
struct Shape {
  bool isFloat = false, isInt = false;
  int comps = 1, cols = 0;
  int scalars() const { return cols ? cols * comps : comps; }
};

struct Parser {
  std::map<std::string, Shape> types;        // type id -> shape
  std::map<std::string, std::string> typeOf; // value id -> type id
  std::string glslSet;                       // id of the GLSL.std.450 import
  Counts counts;
  std::string error;

  const Shape* shapeOfValue(const std::string& id) const {
    auto t = typeOf.find(id);
    if (t == typeOf.end()) return nullptr;
    auto s = types.find(t->second);
    return s == types.end() ? nullptr : &s->second;
  }
  const Shape* shapeOfType(const std::string& id) const {
    auto s = types.find(id);
    return s == types.end() ? nullptr : &s->second;
  }
  void fail(const std::string& line, const std::string& why) {
    if (error.empty()) error = why + " in: " + line;
  }

  void declareType(const std::vector<std::string>& t) {
    const std::string& op = t[2];
    Shape s;
    if (op == "OpTypeFloat") s.isFloat = true;
    else if (op == "OpTypeInt") s.isInt = true;
    else if (op == "OpTypeVector" || op == "OpTypeMatrix") {
      const Shape* e = t.size() > 4 ? shapeOfType(t[3]) : nullptr;
      if (!e) return;
      s = *e;
      if (op == "OpTypeVector") s.comps = std::atoi(t[4].c_str());
      else s.cols = std::atoi(t[4].c_str());
    } else {
      return;  // pointers, structs, arrays, functions: never operands of arithmetic we count
    }
    types[t[0]] = s;
  }

  // One instruction inside a function body: `%r = OpX %type operands...` or `OpX operands`.
  void count(const std::vector<std::string>& t, const std::string& line) {
    if (t.size() < 4 || t[1] != "=") return;
    const std::string& op = t[2];
    const Shape* res = shapeOfType(t[3]);
    const int n = res ? res->scalars() : 1;
    Counts& c = counts;
    auto hit = [&](const std::string& key) { ++c.histogram[key]; };
    auto operand = [&](size_t i) -> const Shape* {
      const Shape* s = i < t.size() ? shapeOfValue(t[i]) : nullptr;
      if (!s) fail(line, "unknown operand type");
      return s;
    };
    if (res && res->isInt) {
      static const char* kIntOps[] = {"OpIAdd", "OpISub", "OpIMul", "OpSDiv", "OpUDiv",
                                      "OpSMod", "OpUMod", "OpSRem", "OpShiftLeftLogical",
                                      "OpShiftRightLogical", "OpShiftRightArithmetic",
                                      "OpBitwiseAnd", "OpBitwiseOr", "OpBitwiseXor"};
      for (const char* k : kIntOps)
        if (op == k) { c.intOps += uint64_t(n); hit(op); }
      return;
    }
    if (op == "OpFAdd" || op == "OpFSub") { c.add += uint64_t(n); hit(op); }
    else if (op == "OpFMul" || op == "OpVectorTimesScalar" || op == "OpMatrixTimesScalar" ||
             op == "OpOuterProduct") { c.mul += uint64_t(n); hit(op); }
    else if (op == "OpFDiv") { c.div += uint64_t(n); hit(op); }
    else if (op == "OpFRem" || op == "OpFMod") { c.other += uint64_t(n); hit(op); }
    else if (op == "OpDot") {
      if (const Shape* a = operand(4)) { c.mul += uint64_t(a->comps); c.add += uint64_t(a->comps - 1); }
      hit(op);
    } else if (op == "OpMatrixTimesVector") {
      if (const Shape* m = operand(4)) {
        c.mul += uint64_t(m->cols * m->comps);
        c.add += uint64_t((m->cols - 1) * m->comps);
      }
      hit(op);
    } else if (op == "OpVectorTimesMatrix") {
      if (const Shape* m = operand(5)) {
        c.mul += uint64_t(m->cols * m->comps);
        c.add += uint64_t(m->cols * (m->comps - 1));
      }
      hit(op);
    } else if (op == "OpMatrixTimesMatrix") {
      const Shape* a = operand(4);
      const Shape* b = operand(5);
      if (a && b) {
        c.mul += uint64_t(b->cols * a->cols * a->comps);
        c.add += uint64_t(b->cols * (a->cols - 1) * a->comps);
      }
      hit(op);
    } else if (op == "OpExtInst" && t.size() > 5 && t[4] == glslSet) {
      countGlsl(t, line, n);
    }
  }

  void countGlsl(const std::vector<std::string>& t, const std::string& line, int n) {
    Counts& c = counts;
    const std::string& f = t[5];
    const Shape* a = t.size() > 6 ? shapeOfValue(t[6]) : nullptr;
    if (!a) return fail(line, "unknown operand type");
    const uint64_t k = uint64_t(a->comps);
    ++c.histogram[f];
    if (f == "Fma") { c.mul += uint64_t(n); c.add += uint64_t(n); }
    else if (f == "Sqrt") c.sqrt += uint64_t(n);
    else if (f == "Normalize") { c.mul += 2 * k; c.add += k - 1; c.other += 1; }
    else if (f == "Length") { c.mul += k; c.add += k - 1; c.sqrt += 1; }
    else if (f == "Distance") { c.mul += k; c.add += 2 * k - 1; c.sqrt += 1; }
    else if (f == "Cross") { c.mul += 6; c.add += 3; }
    else if (f == "FMix") { c.mul += uint64_t(n); c.add += 2 * uint64_t(n); }
    else if (f == "Reflect") { c.mul += 2 * k + 1; c.add += 2 * k - 1; }
    else if (f == "FClamp") c.other += 2 * uint64_t(n);
    else if (f == "Fract") { c.add += uint64_t(n); c.other += uint64_t(n); }
    else if (f == "Step") { /* a comparison and a select, free as in the shim */ }
    else {
      static const char* kOther[] = {"InverseSqrt", "Sin", "Cos", "Tan", "Asin", "Acos",
                                     "Atan", "Atan2", "Exp", "Log", "Exp2", "Log2", "Pow",
                                     "FAbs", "FSign", "Floor", "Ceil", "Trunc", "Round",
                                     "RoundEven", "FMin", "FMax", "NMin", "NMax", "SmoothStep"};
      bool known = false;
      for (const char* o : kOther) known = known || f == o;
      if (!known) ++c.unknownExtInsts[f];
      c.other += uint64_t(n);
    }
  }
};

std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> t;
  std::istringstream in(line);
  for (std::string w; in >> w;) t.push_back(w);
  return t;
}

// spirv-opt -O (SPIRV-Tools 2023) as listed by --print-all, without simplify-instructions.
const char* kNoFoldPasses =
    "--wrap-opkill --eliminate-dead-branches --merge-return --inline-entry-points-exhaustive "
    "--eliminate-dead-functions --eliminate-dead-code-aggressive --private-to-local "
    "--eliminate-local-single-block --eliminate-local-single-store "
    "--eliminate-dead-code-aggressive --scalar-replacement=100 --convert-local-access-chains "
    "--eliminate-local-single-block --eliminate-local-single-store "
    "--eliminate-dead-code-aggressive --ssa-rewrite --eliminate-dead-code-aggressive --ccp "
    "--eliminate-dead-code-aggressive --loop-unroll --eliminate-dead-branches "
    "--redundancy-elimination --combine-access-chains --scalar-replacement=100 "
    "--convert-local-access-chains --eliminate-local-single-block --eliminate-local-single-store "
    "--eliminate-dead-code-aggressive --ssa-rewrite --eliminate-dead-code-aggressive --vector-dce "
    "--eliminate-dead-inserts --eliminate-dead-branches --if-conversion --copy-propagate-arrays "
    "--reduce-load-size --eliminate-dead-code-aggressive --merge-blocks --redundancy-elimination "
    "--eliminate-dead-branches --merge-blocks";

std::string passesFor(Optimise opt) {
  switch (opt) {
    case Optimise::Full: return "-O";
    case Optimise::NoFold: return kNoFoldPasses;
    // Inlining alone leaves the callees in the module: drop them, or they would count twice.
    case Optimise::InlineOnly: break;
  }
  return "--inline-entry-points-exhaustive --eliminate-dead-functions";
}

}  // namespace

TempDir::TempDir(const std::string& prefix) {
  std::string tmpl = (fs::temp_directory_path() / (prefix + "-XXXXXX")).string();
  if (mkdtemp(tmpl.data())) path = tmpl;
}

TempDir::~TempDir() {
  std::error_code ec;
  if (!path.empty()) fs::remove_all(path, ec);
}

Counts& Counts::operator+=(const Counts& o) {
  mul += o.mul, add += o.add, div += o.div, sqrt += o.sqrt, other += o.other, intOps += o.intOps;
  for (const auto& [k, v] : o.histogram) histogram[k] += v;
  for (const auto& [k, v] : o.unknownExtInsts) unknownExtInsts[k] += v;
  return *this;
}

std::string shortText(const Counts& c) {
  return std::to_string(c.mul) + "/" + std::to_string(c.add) + "/" + std::to_string(c.div) + "/" +
         std::to_string(c.sqrt) + "/" + std::to_string(c.other);
}

std::string histogramDiff(const Counts& a, const Counts& b) {
  std::map<std::string, long long> d;
  for (const auto& [k, v] : b.histogram) d[k] += (long long)v;
  for (const auto& [k, v] : a.histogram) d[k] -= (long long)v;
  std::string out;
  for (const auto& [k, v] : d) {
    if (!v) continue;
    if (!out.empty()) out += ", ";
    out += (v > 0 ? "+" : "") + std::to_string(v) + " " + k;
  }
  return out;
}

Result<Counts> countDisassembly(const std::string& text) {
  Parser p;
  bool inFunction = false;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> t = tokens(line);
    if (t.empty() || t[0][0] == ';') continue;
    if (t.size() >= 3 && t[1] == "=" && t[2] == "OpExtInstImport") {
      if (line.find("\"GLSL.std.450\"") != std::string::npos) p.glslSet = t[0];
      continue;
    }
    if (t.size() >= 3 && t[1] == "=" && t[2].rfind("OpType", 0) == 0) {
      p.declareType(t);
      continue;
    }
    const std::string& op = t.size() >= 3 && t[1] == "=" ? t[2] : t[0];
    if (op == "OpFunction") inFunction = true;
    if (op == "OpFunctionEnd") inFunction = false;
    // Every value (constants and globals too) has its result type as first operand.
    if (t.size() >= 4 && t[1] == "=") p.typeOf[t[0]] = t[3];
    if (inFunction) p.count(t, line);
  }
  if (!p.error.empty()) return Result<Counts>::fail("SPIR-V count: " + p.error);
  return p.counts;
}

Result<std::string> compileToDisassembly(const std::string& source, const std::string& stage,
                                         Optimise opt, const std::string& name) {
  using R = Result<std::string>;
  // Same text, stage, passes and libraries: the same disassembly (spirv_cache.h).
  const std::string key = cacheKey(source, stage, "glslang -G --aml; spirv-opt " + passesFor(opt));
  if (auto cached = cachedDisassembly(key)) return *cached;
  // -G: SPIR-V for OpenGL (plain uniforms allowed); --aml: locations for those uniforms.
  auto module = compileGlsl(source, stage, "-G --aml", name);
  if (!module) return R::fail(module.error());
  auto optimised = optimiseSpirv(*module, passesFor(opt), name);
  if (!optimised) return R::fail(optimised.error());
  auto text = disassembleSpirv(*optimised, name);
  if (!text) return R::fail(text.error());
  storeDisassembly(key, *text);
  return text;
}

Result<std::vector<uint32_t>> compileToBinary(const std::string& source, const std::string& stage,
                                              const std::string& flags, const std::string& name) {
  using R = Result<std::vector<uint32_t>>;
  // The module is a pure function of the text, the stage, the flags and glslang (spirv_cache.h):
  // a run with the cache filled skips glslang for all of motorbench isa's ~140 stages.
  const std::string key = cacheKey(source, stage, "glslang " + flags + " (binary module)");
  std::string bytes = cachedDisassembly(key).value_or("");
  if (bytes.empty() || bytes.size() % 4) {
    auto module = compileGlsl(source, stage, flags, name);
    if (!module) return R::fail(module.error());
    bytes.assign(reinterpret_cast<const char*>(module->data()), module->size() * 4);
    storeDisassembly(key, bytes);
  }
  std::vector<uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), bytes.size());
  return words;
}

Result<Counts> countSource(const std::string& source, const std::string& stage, Optimise opt,
                           const std::string& name) {
  auto dis = compileToDisassembly(source, stage, opt, name);
  if (!dis) return Result<Counts>::fail(dis.error());
  auto c = countDisassembly(*dis);
  if (!c) return Result<Counts>::fail(name + ": " + c.error());
  return c;
}

}  // namespace mb::spirv
