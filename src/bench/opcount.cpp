#include "bench/opcount.hpp"

#include <functional>
#include <map>
#include <set>

#include "runner/runner.hpp"

namespace doublet::bench {
namespace {

enum Op : uint32_t {
  ExtInstImport = 11, ExtInst = 12, EntryPoint = 15, TypeBool = 20, TypeFloat = 22, TypeVector = 23,
  TypeMatrix = 24, TypePointer = 32, Function = 54, FunctionParameter = 55, FunctionEnd = 56,
  FunctionCall = 57, FNegate = 127, FAdd = 129, FSub = 131, FMul = 133, FDiv = 136, FRem = 140, FMod = 141,
  VectorTimesScalar = 142, MatrixTimesScalar = 143, MatrixTimesVector = 145, Dot = 148, Select = 169,
  Label = 248, Branch = 249, BranchConditional = 250, Switch = 251, Return = 253, ReturnValue = 254,
};

// One basic block: its own float operations, the functions it calls, its successors.
struct Block {
  double own = 0;
  std::vector<uint32_t> callees;
  std::vector<uint32_t> next;  // successor labels; empty: returns
};

struct Fn {
  std::vector<uint32_t> order;           // labels in module order (the first is the entry)
  std::map<uint32_t, Block> blocks;
};

}  // namespace

double count_main_float_ops(const std::vector<uint32_t>& w) {
  if (w.size() < 5 || w[0] != 0x07230203u) return -1;
  std::map<uint32_t, int> components;        // float/vector/matrix type id -> scalar count
  std::set<uint32_t> float_types;            // type ids whose scalars are float
  std::map<uint32_t, uint32_t> pointee;      // pointer type -> pointee
  std::map<uint32_t, uint32_t> type_of;      // result id -> type id
  std::map<uint32_t, Fn> fns;
  uint32_t main_id = 0, current = 0, glsl_std = 0, block = 0;
  for (size_t i = 5; i < w.size();) {
    const uint32_t count = w[i] >> 16, op = w[i] & 0xffff;
    if (count == 0 || i + count > w.size()) return -1;
    const uint32_t* a = &w[i + 1];  // operands
    switch (op) {
      case ExtInstImport: glsl_std = a[0]; break;
      case EntryPoint:
        if (count > 3 && std::string(reinterpret_cast<const char*>(&a[2])) == "main") main_id = a[1];
        break;
      case TypeFloat: components[a[0]] = 1, float_types.insert(a[0]); break;
      case TypeBool: components[a[0]] = 1; break;
      case TypeVector:
        components[a[0]] = components.count(a[1]) ? components[a[1]] * static_cast<int>(a[2]) : 0;
        if (float_types.count(a[1])) float_types.insert(a[0]);
        break;
      case TypeMatrix:
        components[a[0]] = components.count(a[1]) ? components[a[1]] * static_cast<int>(a[2]) : 0;
        if (float_types.count(a[1])) float_types.insert(a[0]);
        break;
      case TypePointer: pointee[a[0]] = a[2]; break;
      case Function: current = a[1], fns[current], block = 0; break;
      case FunctionEnd: current = 0; break;
      case Label:
        if (current) block = a[0], fns[current].order.push_back(block), fns[current].blocks[block];
        break;
      default: break;
    }
    // Most value instructions are <result type> <result id> ...: remember the type of the id.
    if (count >= 3 && op != TypePointer && op != EntryPoint && op != ExtInstImport && (op < 19 || op > 39))
      type_of[a[1]] = a[0];
    if (current && block && op != Function && op != Label) {
      Block& b = fns[current].blocks[block];
      double& own = b.own;
      std::vector<uint32_t>& callees = b.callees;
      const bool is_float_result = count >= 3 && float_types.count(a[0]);
      const double n = is_float_result && components.count(a[0]) ? components[a[0]] : 1;
      switch (op) {
        case FNegate: case FAdd: case FSub: case FMul: case FDiv: case FRem: case FMod: case VectorTimesScalar:
        case MatrixTimesScalar:
          if (is_float_result) own += n;
          break;
        case Select:
          if (is_float_result) own += n;
          break;
        case ExtInst:
          if (a[2] == glsl_std && is_float_result) {
            if (a[3] == 66 && count > 5) {  // Length: n products, n-1 sums, one sqrt
              const auto t = type_of.find(a[4]);
              own += t != type_of.end() && components.count(t->second) ? 2.0 * components[t->second] : 1;
            } else {
              own += n;
            }
          }
          break;
        case Dot: {
          const auto t = type_of.find(a[2]);
          const int k = t != type_of.end() && components.count(t->second) ? components[t->second] : 3;
          own += 2.0 * k - 1;
          break;
        }
        case MatrixTimesVector: {
          const auto t = type_of.find(a[2]);
          const int mc = t != type_of.end() && components.count(t->second) ? components[t->second] : 16;
          own += 2.0 * mc - n;  // rows*cols products, rows*(cols-1) sums
          break;
        }
        case FunctionCall: callees.push_back(a[2]); break;
        case Branch: b.next = {a[0]}; break;
        case BranchConditional: b.next = {a[1], a[2]}; break;
        case Switch:
          b.next.push_back(a[1]);
          for (uint32_t k = 3; k + 1 < count; k += 2) b.next.push_back(a[k + 1]);
          break;
        default: break;
      }
    }
    i += count;
  }
  if (!main_id || !fns.count(main_id)) return -1;
  // A callee counts along its cheapest path from entry to a return (the rules' branches are
  // rare special cases: the scaled split for |a| > 1e34, df_finish's fallback); main counts every
  // block once (the kernels' steps are straight-line code inside one loop body).
  std::map<uint32_t, double> memo;
  bool callee_loops = false;  // a callee with a back edge: its trip count is not in the code's shape
  std::function<double(uint32_t, int, bool)> total = [&](uint32_t f, int depth, bool all_blocks) -> double {
    if (depth > 64 || !fns.count(f)) return 0;
    if (!all_blocks)
      if (auto it = memo.find(f); it != memo.end()) return it->second;
    Fn& fn = fns[f];
    auto cost = [&](const Block& b) {
      double c = b.own;
      for (uint32_t callee : b.callees) c += total(callee, depth + 1, false);
      return c;
    };
    double result = 0;
    if (all_blocks) {
      for (uint32_t l : fn.order) result += cost(fn.blocks[l]);
      return result;
    }
    // Cheapest entry-to-return path; blocks are in dominance order, so relax in order, and
    // ignore back edges (to earlier blocks).
    std::map<uint32_t, size_t> index;
    for (size_t i = 0; i < fn.order.size(); ++i) index[fn.order[i]] = i;
    std::vector<double> best(fn.order.size(), 1e300);
    if (!fn.order.empty()) best[0] = 0;
    result = 1e300;
    for (size_t i = 0; i < fn.order.size(); ++i) {
      if (best[i] >= 1e300) continue;
      const Block& b = fn.blocks[fn.order[i]];
      const double here = best[i] + cost(b);
      if (b.next.empty()) result = std::min(result, here);
      for (uint32_t n : b.next)
        if (auto it = index.find(n); it != index.end()) {
          if (it->second > i) best[it->second] = std::min(best[it->second], here);
          else callee_loops = true;
        }
    }
    if (result >= 1e300) result = 0;
    return memo[f] = result;
  };
  const double count = total(main_id, 0, true);
  return callee_loops ? -1 : count;
}

double float_ops_per_step(const std::string& glsl8, const std::string& glsl16) {
  std::vector<uint32_t> w8, w16;
  std::string error;
  if (!runner::compile_compute_to_spirv(glsl8, &w8, &error) || !runner::compile_compute_to_spirv(glsl16, &w16, &error))
    return -1;
  const double c8 = count_main_float_ops(w8), c16 = count_main_float_ops(w16);
  if (c8 < 0 || c16 < 0) return -1;
  return (c16 - c8) / 8.0;
}

std::string with_doubled_unroll(const std::string& source, const std::string& step_line) {
  const std::string line = "    " + step_line + "\n";
  std::string block;
  for (int u = 0; u < 8; ++u) block += line;
  const size_t at = source.find(block);
  if (at == std::string::npos) return {};
  return source.substr(0, at) + block + block + source.substr(at + block.size());
}

}  // namespace doublet::bench
