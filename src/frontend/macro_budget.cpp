#include "frontend/macro_budget.hpp"

#include <algorithm>

#include "frontend/text_scan.hpp"

namespace doublet::frontend {

// Weighs a stream of items: each token counts `multiplier` times, where the
// multiplier grows inside the parentheses of a call to a function-like macro
// that repeats its argument.
class MacroBudget::Weigher {
 public:
  explicit Weigher(MacroBudget& budget, const std::vector<int>* params = nullptr)
      : budget_(budget), param_weight_(params ? params->size() : 0, 0.0) {
    if (params)
      for (size_t i = 0; i < params->size(); ++i) param_index_.emplace((*params)[i], i);
  }

  void feed(const Item& item) {
    double repeat = 0;
    bool pastes = false;  // this item names a macro whose expansion pastes a name together
    switch (item.kind) {
      case Item::Plain: add(item.value, multiplier_); break;
      case Item::Open:
        add(1, multiplier_);
        ++depth_;
        if (pending_repeat_ > 1) {
          calls_.push_back({depth_, multiplier_});
          multiplier_ *= pending_repeat_;
        }
        if (pending_pastes_) paste_calls_.push_back(depth_);
        break;
      case Item::Close:
        add(1, multiplier_);
        if (!calls_.empty() && calls_.back().first == depth_) {
          multiplier_ = calls_.back().second;
          calls_.pop_back();
        }
        // CAT(RE,P)(x): the call's result may be a function-like macro's name, called by the next list.
        if (!paste_calls_.empty() && paste_calls_.back() == depth_) {
          paste_calls_.pop_back();
          repeat = budget_.paste_repeat_;
        }
        --depth_;
        break;
      case Item::Ident:
        repeat = ident(item.value);
        pastes = budget_.pastes_in(item.value);
        if (pastes && !budget_.is_function_like(item.value)) repeat = std::max(repeat, budget_.paste_repeat_);
        break;
      case Item::Paste:  // joins two tokens into a name that may be any macro's (value 1), or no macro's
        if (item.value == 0) break;
        add(budget_.paste_size_, multiplier_);
        repeat = budget_.paste_repeat_;
        break;
    }
    pending_repeat_ = repeat;
    pending_pastes_ = pastes;
  }

  double total() const { return total_; }
  double spelled() const { return spelled_; }
  double largest_param_weight() const {
    double most = 1;
    for (double w : param_weight_) most = std::max(most, w);
    return most;
  }

 private:
  void add(double tokens, double multiplier) {
    spelled_ += tokens;
    total_ += tokens * multiplier;
  }
  // Returns how often a following argument list repeats (0: not a call).
  double ident(int id) {
    if (auto it = param_index_.find(id); it != param_index_.end()) {
      param_weight_[it->second] += multiplier_;
      add(1, multiplier_);
      return 0;
    }
    if (!budget_.is_macro(id)) {
      add(1, multiplier_);
      return 0;
    }
    if (budget_.state_[id] == State::Unknown) budget_.measure(id);
    const bool in_progress = budget_.state_[id] == State::InProgress;  // not re-expanded inside itself
    spelled_ += 1;
    total_ += (in_progress ? 1 : budget_.size_[id]) * multiplier_;
    return in_progress ? 0 : budget_.repeat_[id];
  }

  MacroBudget& budget_;
  std::unordered_map<int, size_t> param_index_;  // a macro may have thousands of parameters
  std::vector<double> param_weight_;
  double total_ = 0, spelled_ = 0, multiplier_ = 1, pending_repeat_ = 0;
  bool pending_pastes_ = false;
  int depth_ = 0;
  std::vector<int> paste_calls_;  // paren depths of calls of macros that paste
  std::vector<std::pair<int, double>> calls_;  // (paren depth, multiplier outside)
};

int MacroBudget::intern(std::string_view name) {
  if (auto found = ids_.find(name); found != ids_.end()) return found->second;
  auto [it, added] = ids_.emplace(std::string(name), static_cast<int>(names_.size()));
  if (added) names_.emplace_back(name);
  return it->second;
}

void MacroBudget::tokenize(std::string_view text, std::vector<Item>& out, bool intern_names) {
  auto plain = [&out] {
    if (!out.empty() && out.back().kind == Item::Plain) ++out.back().value;
    else out.push_back({Item::Plain, 1});
  };
  while (!text.empty()) {
    const char c = text.front();
    if (is_blank(c)) {
      text.remove_prefix(1);
    } else if (is_word_char(c)) {
      std::string_view word = take_word(text);
      if (is_digit(word.front())) {
        plain();
      } else if (intern_names) {
        out.push_back({Item::Ident, intern(word)});
      } else if (auto it = ids_.find(word); it != ids_.end()) {
        out.push_back({Item::Ident, it->second});
      } else {
        plain();  // named by no definition: cannot expand
      }
    } else if (c == '#' && text.size() > 1 && text[1] == '#') {
      out.push_back({Item::Paste, 1});  // may make any macro's name, until mark_pastes() knows better
      has_paste_ = true;
      text.remove_prefix(2);
    } else {
      if (c == '(') out.push_back({Item::Open, 0});
      else if (c == ')') out.push_back({Item::Close, 0});
      else plain();
      text.remove_prefix(1);
    }
  }
}

void MacroBudget::define(std::string_view rest, const MacroOrigin& origin) {
  skip_blanks(rest);
  std::string_view name = take_word(rest);
  if (name.empty() || is_digit(name.front())) return;  // glslang reports it
  Definition d;
  d.origin = origin;
  if (!rest.empty() && rest.front() == '(') {  // no blank before '(': function-like
    d.function_like = true;
    const size_t close = rest.find(')');
    std::string_view params = rest.substr(1, close == std::string_view::npos ? rest.size() - 1 : close - 1);
    rest.remove_prefix(close == std::string_view::npos ? rest.size() : close + 1);
    while (!params.empty()) {
      skip_blanks(params);
      std::string_view param = take_word(params);
      if (!param.empty()) d.params.push_back(intern(param));
      else if (!params.empty()) params.remove_prefix(1);  // ',' or anything else
    }
  }
  tokenize(rest, d.body, true);
  const int id = intern(name);
  if (definitions_.size() <= static_cast<size_t>(id)) definitions_.resize(static_cast<size_t>(id) + 1);
  if (std::any_of(d.body.begin(), d.body.end(), [](const Item& i) { return i.kind == Item::Paste; })) {
    if (pastes_.size() <= static_cast<size_t>(id)) pastes_.resize(static_cast<size_t>(id) + 1, false);
    pastes_[static_cast<size_t>(id)] = true;
  }
  definitions_[static_cast<size_t>(id)].push_back(std::move(d));
  state_.clear();  // sizes are recomputed with the new definition
  pastes_settled_ = false;
}

void MacroBudget::add_definitions(std::string_view text, const std::string& file) {
  LogicalLines lines(text);
  for (std::string_view line; lines.next(line);) {
    std::string_view rest;
    if (directive_name(line, rest) == "define") define(rest, {file, lines.line()});
  }
}

void MacroBudget::add_definition(std::string_view name, std::string_view body, const MacroOrigin& origin) {
  define(std::string(name) + " " + std::string(body), origin);
}

// Iterative depth-first walk: a chain of 100,000 macros must not recurse 100,000 deep.
void MacroBudget::size_tables() {
  state_.resize(names_.size(), State::Unknown);
  size_.resize(names_.size(), 1);
  repeat_.resize(names_.size(), 1);
}

void MacroBudget::measure(int root) {
  size_tables();
  if (state_[root] == State::Done) return;
  std::vector<int> stack{root};
  while (!stack.empty()) {
    const int id = stack.back();
    if (state_[id] == State::Done) {
      stack.pop_back();
    } else if (state_[id] == State::Unknown) {
      state_[id] = State::InProgress;
      for (const Definition& d : definitions_[id])
        for (const Item& item : d.body)
          if (item.kind == Item::Ident && is_macro(item.value) && state_[item.value] == State::Unknown)
            stack.push_back(item.value);
    } else {  // everything it names is measured (or is an enclosing macro: not re-expanded)
      measure_definitions(id);
      state_[id] = State::Done;
      stack.pop_back();
    }
  }
}

void MacroBudget::measure_definitions(int id) {
  double size = 1, repeat = 1;
  for (const Definition& d : definitions_[id]) {
    Weigher w(*this, &d.params);
    for (const Item& item : d.body) w.feed(item);
    size = std::max(size, w.total());
    repeat = std::max(repeat, w.largest_param_weight());
  }
  size_[id] = size;
  repeat_[id] = repeat;
}

// A paste chain (a ## b ## c) makes one token whose name holds the chain's spelled fragments (the
// tokens that are not parameters) in order: `u_##n` starts with u_, `y##_to_##x` contains _to_.
// When no macro's name holds them, the result names no macro: its pastes weigh nothing more
// (value 0). Chains of parameters only, or with a number, may still make any name (value 1).
// glslang's constantUnaryConversion.comp was refused as 10^15 tokens before; it expands to a few
// hundred.
void MacroBudget::mark_pastes() {
  std::vector<const std::string*> macro_names;
  for (size_t id = 0; id < definitions_.size(); ++id)
    if (!definitions_[id].empty()) macro_names.push_back(&names_[id]);
  auto names_a_macro = [&](const std::vector<std::string_view>& fragments) {
    for (const std::string* name : macro_names) {
      size_t at = 0;
      bool holds = true;
      for (std::string_view f : fragments) {
        const size_t found = name->find(f, at);
        if (found == std::string::npos) {
          holds = false;
          break;
        }
        at = found + f.size();
      }
      if (holds) return true;
    }
    return false;
  };
  for (size_t id = 0; id < definitions_.size(); ++id) {
    bool any = false;
    for (Definition& d : definitions_[id]) {
      std::vector<Item>& body = d.body;
      for (size_t i = 0; i < body.size(); ++i) {
        if (body[i].kind != Item::Paste || i == 0) continue;
        // The chain: operands body[start], body[start+2], ... joined by pastes.
        const size_t start = i - 1;
        size_t end = i + 1;
        while (end + 1 < body.size() && body[end + 1].kind == Item::Paste) end += 2;
        std::vector<std::string_view> fragments;
        bool open = false;  // a number or a token the scan cannot spell: may make any name
        for (size_t k = start; k <= end && k < body.size(); k += 2) {
          const Item& operand = body[k];
          if (operand.kind != Item::Ident) {
            open = true;
          } else if (std::find(d.params.begin(), d.params.end(), operand.value) == d.params.end()) {
            fragments.push_back(names_[static_cast<size_t>(operand.value)]);
          }
        }
        const int may_name = open || fragments.empty() || names_a_macro(fragments) ? 1 : 0;
        for (size_t k = start + 1; k <= end && k < body.size(); k += 2) body[k].value = may_name;
        any = any || may_name;
        i = end;
      }
    }
    if (id < pastes_.size()) pastes_[id] = any;
  }
}

// Each round weighs every macro with a paste counting as the largest macro of the round before,
// so round k follows pastes that make pasting macros' names k deep; it stops when nothing grows.
void MacroBudget::settle_pastes() {
  if (pastes_settled_) return;
  pastes_settled_ = true;
  paste_size_ = 1;
  paste_repeat_ = 0;
  if (!has_paste_) return;
  mark_pastes();
  for (int round = 0; round < kPasteRounds; ++round) {
    state_.assign(names_.size(), State::Unknown);
    size_tables();
    double largest_size = 1, largest_repeat = 0;
    for (size_t id = 0; id < definitions_.size(); ++id) {
      if (definitions_[id].empty()) continue;
      measure(static_cast<int>(id));
      largest_size = std::max(largest_size, size_[id]);
      largest_repeat = std::max(largest_repeat, repeat_[id]);
    }
    const bool settled = largest_size <= paste_size_ && largest_repeat <= paste_repeat_;
    paste_size_ = std::max(paste_size_, largest_size);
    paste_repeat_ = std::max(paste_repeat_, largest_repeat);
    if (settled) break;
  }
  state_.assign(names_.size(), State::Unknown);  // measured again with the final paste weights
}

MacroBudget::Weight MacroBudget::weigh(std::string_view text) {
  settle_pastes();
  size_tables();
  Weigher w(*this);
  std::vector<Item> items;
  LogicalLines lines(text);
  for (std::string_view line; lines.next(line);) {
    std::string_view rest;
    const std::string_view directive = directive_name(line, rest);
    if (directive.empty()) rest = line;
    else if (directive != "if" && directive != "elif") continue;
    items.clear();
    tokenize(rest, items, false);
    for (const Item& item : items) w.feed(item);
  }
  return {w.spelled(), w.total()};
}

MacroBudget::Largest MacroBudget::largest_macro() {
  settle_pastes();
  Largest largest;
  for (size_t id = 0; id < definitions_.size(); ++id) {
    if (definitions_[id].empty()) continue;
    measure(static_cast<int>(id));
    if (size_[id] > largest.tokens) largest = {names_[id], definitions_[id].back().origin, size_[id]};
  }
  return largest;
}

}  // namespace doublet::frontend
