#include "harness/sweep.h"

#include "core/io.h"
#include "core/json.h"
#include "core/registry.h"
#include "generators/family.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <sstream>
#include <tuple>

namespace pd {
namespace {

std::string read_file(const std::string& path) {
  std::optional<std::string> text = read_file_bytes(path);
  if (!text) throw SweepError("cannot read sweeps file " + path);
  return std::move(*text);
}

const Json& member(const Json& object, const std::string& key, const std::string& where) {
  const Json* v = object.get(key);
  if (!v) throw SweepError(where + ": missing \"" + key + "\"");
  return *v;
}

double positive_number(const Json& object, const std::string& key, const std::string& where) {
  const Json& v = member(object, key, where);
  const double x = v.is_number() ? v.number() : -1;
  if (!(x > 0)) throw SweepError(where + ": \"" + key + "\" must be a positive number");
  return x;
}

std::size_t count_of(const Json& v, const std::string& where) {
  const double x = v.is_number() ? v.number() : -1;
  if (!(x >= 0) || x != static_cast<double>(static_cast<std::size_t>(x)))
    throw SweepError(where + ": expected a non-negative integer");
  return static_cast<std::size_t>(x);
}

std::vector<const Json*> array_items(const Json& v, const std::string& where) {
  if (!v.is_array() || v.items.empty()) throw SweepError(where + ": expected a non-empty array");
  std::vector<const Json*> items;
  for (const Json& item : v.items) items.push_back(&item);
  return items;
}

// A reflex rule as written in the file: a number, "default", or "n/K" / "P*n/K".
std::string rule_text(const Json& v, const std::string& where) {
  if (v.is_number()) return std::to_string(count_of(v, where));
  if (v.type == Json::Type::String) return v.text;
  throw SweepError(where + ": a reflex rule is a number, \"default\" or a fraction of n such as \"n/4\"");
}

// Numerator and denominator of a rule "n", "n/K", "P*n" or "P*n/K".
bool parse_fraction(const std::string& rule, std::size_t& p, std::size_t& k) {
  std::size_t at = 0;
  p = 1;
  k = 1;
  const auto digits = [&](std::size_t& out) {
    const std::size_t start = at;
    while (at < rule.size() && std::isdigit(static_cast<unsigned char>(rule[at]))) ++at;
    if (at == start) return false;
    out = std::stoul(rule.substr(start, at - start));
    return true;
  };
  if (std::isdigit(static_cast<unsigned char>(rule[0]))) {
    if (!digits(p) || at >= rule.size() || rule[at++] != '*') return false;
  }
  if (at >= rule.size() || rule[at++] != 'n') return false;
  if (at < rule.size() && (rule[at++] != '/' || !digits(k) || k == 0)) return false;
  return at == rule.size();
}

void check_rule(const std::string& rule, const std::string& where) {
  std::size_t p, k;
  const bool number = !rule.empty() && std::all_of(rule.begin(), rule.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
  });
  if (!number && rule != "default" && !parse_fraction(rule, p, k))
    throw SweepError(where + ": bad reflex rule \"" + rule + "\" (a number, \"default\", \"n/K\" or \"P*n/K\")");
}

std::size_t resolve_reflex(const std::string& rule, std::size_t family_default, std::size_t n) {
  if (rule == "default") return family_default;
  std::size_t p, k;
  if (parse_fraction(rule, p, k)) return n * p / k;
  return std::stoul(rule);
}

constexpr const char* kCorpusPrefix = "dir:";

bool names_corpus(const Json* item) {
  return item->type == Json::Type::String && item->text.rfind(kCorpusPrefix, 0) == 0;
}

// A curve's corpora: their folders, relative ones read from `base`, the sweeps file's folder.
std::vector<std::string> select_corpora(const Json& v, const std::string& where, const std::filesystem::path& base) {
  std::vector<std::string> paths;
  for (const Json* item : array_items(v, where + " families")) {
    if (!names_corpus(item)) throw SweepError(where + ": a curve holds corpora (\"dir:PATH\") or families, not both");
    const std::filesystem::path folder(item->text.substr(std::char_traits<char>::length(kCorpusPrefix)));
    if (folder.empty()) throw SweepError(where + ": \"dir:\" needs a folder");
    std::filesystem::path resolved = (folder.is_relative() ? base / folder : folder).lexically_normal();
    if (!resolved.has_filename()) resolved = resolved.parent_path();  // "dir:x/" is "dir:x"
    paths.push_back(resolved.string());
  }
  return paths;
}

bool curve_of_corpora(const Json& families) {
  return families.is_array() && !families.items.empty() && names_corpus(&families.items[0]);
}

// A curve of corpora: every file of each ("vs-n corpus"), or with "n" the files nearest to each n
// ("vs-n nearest").
Sweep::Curve corpus_curve(const Json& entry, const std::string& where, const std::filesystem::path& base) {
  if (member(entry, "vs", where).text != "n") throw SweepError(where + ": a curve of corpora is \"vs\": \"n\"");
  if (entry.get("r") || entry.get("h"))
    throw SweepError(where + ": a corpus's files have their own r and h; a curve of corpora takes neither \"r\" nor \"h\"");
  const Json* ns = entry.get("n");
  Sweep::Curve c{ns ? "vs-n nearest" : "vs-n corpus", select_corpora(member(entry, "families", where), where, base), {}, true};
  if (ns)
    for (const Json* v : array_items(*ns, where + " n")) c.points.push_back({count_of(*v, where + " n"), "", std::nullopt});
  return c;
}

// The curve's families, and whether they are the families with holes (a curve holds one kind).
std::vector<std::string> select_families(const Json& v, const std::string& where, bool& with_holes) {
  std::vector<std::string> names;
  with_holes = v.type == Json::Type::String && v.text == "holes";
  if (with_holes) {
    for (const HoleFamily& f : hole_families()) names.push_back(f.name);
    return names;
  }
  if (v.type == Json::Type::String && (v.text == "all" || v.text == "controls_r")) {
    for (const Family& f : families())
      if (v.text == "all" || f.controls_r) names.push_back(f.name);
    return names;
  }
  std::size_t holed = 0;
  for (const Json* item : array_items(v, where + " families")) {
    if (names_corpus(item)) throw SweepError(where + ": a curve holds corpora (\"dir:PATH\") or families, not both");
    const bool known = item->type == Json::Type::String && (find_family(item->text) || find_hole_family(item->text));
    if (!known) throw SweepError(where + ": unknown family " + (item->type == Json::Type::String ? item->text : "?"));
    names.push_back(item->text);
    holed += find_hole_family(item->text) != nullptr;
  }
  if (holed != 0 && holed != names.size())
    throw SweepError(where + ": a curve holds families with holes or families without, not both");
  with_holes = holed != 0;
  return names;
}

// "budget_seconds_for": {"algorithm": seconds, ...}, optional.
std::map<std::string, double> budgets_by_algorithm(const Json* v, const std::string& where) {
  std::map<std::string, double> budgets;
  if (!v) return budgets;
  if (!v->is_object()) throw SweepError(where + ": \"budget_seconds_for\" must be an object of algorithm names and seconds");
  for (const auto& [name, value] : v->fields) {
    if (!find_algorithm(name)) throw SweepError(where + ": budget_seconds_for: unknown algorithm " + name);
    budgets[name] = positive_number(*v, name, where + " budget_seconds_for");
  }
  return budgets;
}

std::vector<std::string> select_algorithms(const Json* v, const std::string& where) {
  std::vector<std::string> names;
  if (!v || (v->type == Json::Type::String && v->text == "all")) {
    for (const Algorithm& a : algorithms()) names.push_back(a.name);
    return names;
  }
  for (const Json* item : array_items(*v, where + " algorithms")) {
    if (item->type != Json::Type::String || !find_algorithm(item->text))
      throw SweepError(where + ": unknown algorithm " + (item->type == Json::Type::String ? item->text : "?"));
    names.push_back(item->text);
  }
  return names;
}

// One entry of "curves": {"vs": "n", "n": [...], "r": [rules]} is one curve per rule;
// {"vs": "r", "n": [...], "r": [rules]} is one curve per n. For the families with holes "h": [...]
// is required: "vs": "n" and "vs": "r" give one curve per h as well, and {"vs": "h", "n": [...],
// "r": [rules], "h": [...]} one curve per n and rule.
std::vector<Sweep::Curve> expand_curves(const Json& entry, const std::string& where, const std::filesystem::path& base) {
  if (curve_of_corpora(member(entry, "families", where))) return {corpus_curve(entry, where, base)};
  const Json& vs = member(entry, "vs", where);
  if (vs.type != Json::Type::String || (vs.text != "n" && vs.text != "r" && vs.text != "h"))
    throw SweepError(where + ": \"vs\" must be \"n\", \"r\" or \"h\"");
  bool with_holes = false;
  const auto families = select_families(member(entry, "families", where), where, with_holes);
  std::vector<std::size_t> ns;
  for (const Json* v : array_items(member(entry, "n", where), where + " n")) ns.push_back(count_of(*v, where + " n"));
  std::vector<std::string> rules;
  for (const Json* v : array_items(member(entry, "r", where), where + " r")) {
    rules.push_back(rule_text(*v, where + " r"));
    check_rule(rules.back(), where);
  }
  std::vector<std::optional<std::size_t>> hs{std::nullopt};
  if (with_holes) {
    hs.clear();
    for (const Json* v : array_items(member(entry, "h", where), where + " h")) hs.push_back(count_of(*v, where + " h"));
  } else if (entry.get("h") || vs.text == "h") {
    throw SweepError(where + ": \"h\" is for the families with holes (\"families\": \"holes\")");
  }
  const auto with_h = [](const std::string& label, std::optional<std::size_t> h) {
    return h ? label + " h=" + std::to_string(*h) : label;
  };
  std::vector<Sweep::Curve> curves;
  if (vs.text == "n") {
    for (const auto& h : hs)
      for (const std::string& rule : rules) {
        Sweep::Curve c{with_h("vs-n r=" + rule, h), families, {}};
        for (std::size_t n : ns) c.points.push_back({n, rule, h});
        curves.push_back(std::move(c));
      }
  } else if (vs.text == "r") {
    for (const auto& h : hs)
      for (std::size_t n : ns) {
        Sweep::Curve c{with_h("vs-r n=" + std::to_string(n), h), families, {}};
        for (const std::string& rule : rules) c.points.push_back({n, rule, h});
        curves.push_back(std::move(c));
      }
  } else {
    for (std::size_t n : ns)
      for (const std::string& rule : rules) {
        Sweep::Curve c{"vs-h n=" + std::to_string(n) + " r=" + rule, families, {}};
        for (const auto& h : hs) c.points.push_back({n, rule, h});
        curves.push_back(std::move(c));
      }
  }
  return curves;
}

std::string sweep_names(const Json& root) {
  std::string names;
  for (const auto& [name, value] : root.fields) names += (names.empty() ? "" : ", ") + name;
  return names;
}

// Reads every corpus the curves name, once; two corpora of one name would give their keys one name.
void read_corpora(Sweep& s, const std::string& where, const CorpusProgress& progress) {
  std::map<std::string, std::string> path_of_name;
  for (const Sweep::Curve& c : s.curves) {
    if (!c.corpora) continue;
    for (const std::string& path : c.families) {
      if (s.corpora.count(path)) continue;
      try {
        s.corpora[path] = read_corpus(path, progress);
      } catch (const std::runtime_error& e) {
        throw SweepError(where + ": " + e.what());
      }
      const std::string& name = s.corpora[path].name;
      if (find_family(name) || find_hole_family(name))
        throw SweepError(where + ": corpus " + path + " is named like the family " + name + "; rename its folder");
      if (path_of_name.count(name))
        throw SweepError(where + ": corpora " + path_of_name[name] + " and " + path + " have one name, " + name);
      path_of_name[name] = path;
    }
  }
}

}  // namespace

std::string SweepPolygon::id() const {
  const std::string size = "/n:" + std::to_string(n) + "/r:" + std::to_string(r);
  if (file) return family + "/" + file->name + size + "/h:" + std::to_string(file->h);
  return family + size + (h ? "/h:" + std::to_string(*h) : "") + "/seed:" + std::to_string(seed);
}

std::string default_sweeps_file() { return PD_SOURCE_DIR "/harness/sweeps.json"; }

Sweep load_sweep(const std::string& path, const std::string& name, const CorpusProgress& progress) {
  Json root;
  try {
    root = parse_json(read_file(path));
  } catch (const JsonError& e) {
    throw SweepError(path + ": " + e.what());
  }
  const Json* spec = root.is_object() ? root.get(name) : nullptr;
  if (!spec || !spec->is_object())
    throw SweepError("no sweep '" + name + "' in " + path + "; it defines: " + sweep_names(root));
  const std::string where = path + ": sweep " + name;
  Sweep s;
  s.name = name;
  if (const Json* d = spec->get("description")) s.description = d->text;
  s.algorithms = select_algorithms(spec->get("algorithms"), where);
  for (const Json* v : array_items(member(*spec, "seeds", where), where + " seeds")) s.seeds.push_back(count_of(*v, where + " seeds"));
  s.min_time = positive_number(*spec, "min_time", where);
  s.budget_seconds = positive_number(*spec, "budget_seconds", where);
  s.budget_seconds_for = budgets_by_algorithm(spec->get("budget_seconds_for"), where);
  s.timeout_seconds = positive_number(*spec, "timeout_seconds", where);
  const auto entries = array_items(member(*spec, "curves", where), where + " curves");
  for (std::size_t i = 0; i < entries.size(); ++i)
    for (Sweep::Curve& c : expand_curves(*entries[i], where + " curve " + std::to_string(i + 1),
                                         std::filesystem::path(path).parent_path()))
      s.curves.push_back(std::move(c));
  read_corpora(s, where, progress);
  return s;
}

std::vector<std::pair<std::string, std::string>> refused_files(const Sweep& sweep) {
  std::map<std::string, const Corpus*> by_name;
  for (const auto& [path, corpus] : sweep.corpora) by_name[corpus.name] = &corpus;
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [name, corpus] : by_name)
    for (const CorpusFile& f : corpus->files)
      if (f.refused) out.emplace_back(name + "/" + f.name, *f.refused);
  return out;
}

// The r of a grid point at a seed, or nothing when the family cannot realise the point. A family whose
// r is an outcome realises only the rule "default", with the r its method gives at (n, seed).
std::optional<std::size_t> feasible_reflex(const std::string& family_name, const Sweep::GridPoint& at,
                                           std::uint64_t seed) {
  if (const HoleFamily* f = find_hole_family(family_name)) {
    const std::size_t r = resolve_reflex(at.rule, f->default_reflex(at.n, *at.h), at.n);
    if (f->infeasible(at.n, r, *at.h)) return std::nullopt;
    return r;
  }
  const Family& f = *find_family(family_name);
  if (f.r_is_outcome) {
    if (at.rule != "default" || f.n_infeasible(at.n)) return std::nullopt;
    return reflex_outcome(f.name, at.n, seed);
  }
  const std::size_t r = resolve_reflex(at.rule, f.default_reflex(at.n), at.n);
  if (f.infeasible(at.n, r)) return std::nullopt;
  return r;
}

namespace {

// The files of corpus c on a curve of corpora: every accepted one, or the seed-th nearest to each n.
std::vector<const CorpusFile*> chosen_files(const Corpus& c, const Sweep::Curve& curve,
                                            const std::vector<std::uint64_t>& seeds) {
  if (curve.points.empty()) return c.accepted();
  std::vector<const CorpusFile*> chosen;
  for (const Sweep::GridPoint& at : curve.points)
    for (std::uint64_t seed : seeds)
      if (const CorpusFile* f = c.nearest(at.n, seed)) chosen.push_back(f);
  return chosen;
}

}  // namespace

std::vector<SweepPolygon> sweep_polygons(const Sweep& sweep) {
  // By family (or corpus), n, r, h, seed, then file name.
  using Key = std::tuple<std::string, std::size_t, std::size_t, std::optional<std::size_t>, std::uint64_t, std::string>;
  std::map<Key, std::vector<std::string>> grid;
  std::map<Key, const CorpusFile*> files;
  const auto add = [&](const Key& key, const std::string& label) {
    auto& curves = grid[key];
    if (std::find(curves.begin(), curves.end(), label) == curves.end()) curves.push_back(label);
  };
  for (const Sweep::Curve& curve : sweep.curves) {
    if (curve.corpora) {
      for (const std::string& path : curve.families) {
        const Corpus& c = sweep.corpora.at(path);
        for (const CorpusFile* f : chosen_files(c, curve, sweep.seeds)) {
          const Key key{c.name, f->n, f->r, f->h, 0, f->name};
          files[key] = f;
          add(key, curve.label);
        }
      }
      continue;
    }
    for (const std::string& family_name : curve.families) {
      for (const Sweep::GridPoint& at : curve.points)
        for (std::uint64_t seed : sweep.seeds)
          if (const std::optional<std::size_t> r = feasible_reflex(family_name, at, seed))
            add({family_name, at.n, *r, at.h, seed, ""}, curve.label);
    }
  }
  std::vector<SweepPolygon> polygons;
  for (auto& [key, curves] : grid) {
    const auto file = files.find(key);
    polygons.push_back({std::get<0>(key), std::get<1>(key), std::get<2>(key), std::get<3>(key), std::get<4>(key),
                        std::move(curves), file == files.end() ? nullptr : file->second});
  }
  return polygons;
}

Shard parse_shard(const std::string& text) {
  Shard s;
  char slash = 0;
  std::istringstream in(text);
  if (!(in >> s.index >> slash >> s.count) || slash != '/' || !in.eof() || s.index < 1 || s.index > s.count)
    throw SweepError("bad --shard '" + text + "'; expected i/k with 1 <= i <= k, e.g. 2/8");
  return s;
}

std::string key_name(const std::string& algorithm, const SweepPolygon& polygon) {
  return algorithm + "/" + polygon.id();
}

}  // namespace pd
