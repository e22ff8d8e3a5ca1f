// chazelle-dobkin's loose rays and X4 tables: see tables.h for the classes, the header of
// algorithms/chazelle_dobkin.cpp for the method and the bounds, and docs/algorithms/chazelle-dobkin.md
// for the reconstructions.
#include "engines/chazelle_dobkin/tables.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace pd::cd {

LooseRays::LooseRays(const Polygon& p, const Patterns& patterns)
    : p_(p), count_(2 * static_cast<int>(patterns.notches().size())) {
  shoot(p, patterns);
  const std::size_t cells = static_cast<std::size_t>(count_) * static_cast<std::size_t>(count_);
  cross_sign_.assign(cells, 0);
  base_side_.assign(cells, 0);
  meet_sign_.assign(cells, 0);
  key_.assign(cells, -1);
  opens_.assign(cells, 0);
  made_at_.assign(cells, -1);
  std::vector<Rational> meet(cells);
  for (int a = 0; a < count_; ++a)
    for (int b = 0; b < count_; ++b) relate(a, b, meet);
  for (int a = 0; a < count_; ++a) list_loose_points(a, sorted_along(a, meet), meet);
}

int LooseRays::side(int a, int b, int c) const {
  const int s = cross_sign(a, b);
  return s == 0 ? base_side_[cell(a, b)] : s * compare(key(b, c), key(b, a));
}

QPoint LooseRays::point(int a, int b) const {
  const Rational s = parameter(a, b);
  return origin_[a] + s * direction_[a];
}

const FilteredPoint& LooseRays::loose_point(int a, int b) {
  std::optional<FilteredPoint>& made = made_[static_cast<std::size_t>(made_at_[cell(a, b)])];
  if (!made) made.emplace(point(a, b));
  return *made;
}

std::vector<LooseRays::Place> LooseRays::terminals() const {
  std::vector<Place> out;
  for (int a = 0; a < count_; ++a) out.insert(out.end(), {start_[a], end_[a]});
  return out;
}

std::size_t LooseRays::terminal(int a, int end) {
  return end == 0 ? 2 * static_cast<std::size_t>(a & ~1) : 2 * static_cast<std::size_t>(a) + 1;
}

bool LooseRays::share_an_end(int a, int b) const {
  for (const Place* x : {&start_[a], &end_[a]})
    for (const Place* y : {&start_[b], &end_[b]})
      if (!Place::before(p_, *x, *y) && !Place::before(p_, *y, *x)) return true;
  return false;
}

void LooseRays::shoot(const Polygon& p, const Patterns& patterns) {
  RayShooter shooter(p);
  for (int a = 0; a < count_; ++a) {
    const std::size_t v = patterns.notches()[static_cast<std::size_t>(notch(a))];
    const std::size_t away = a % 2 == 0 ? p.next(v) : p.prev(v);
    const QPoint z = to_exact(p[v]);
    const Vec u = z - to_exact(p[away]);
    const auto hit = shooter.shoot(v, away, false);
    if (!hit) throw std::logic_error("chazelle-dobkin: a notch's loose ray leaves the polygon");
    const Rational reach = hit_parameter(p, z, u, *hit);
    origin_.push_back(z);
    direction_.push_back(u);
    reach_.push_back(reach);
    at_vertex_.push_back(hit->at_vertex ? 1 : 0);
    start_.push_back({v, true, z});
    end_.push_back({hit->vertex, hit->at_vertex, hit->at_vertex ? to_exact(p[hit->vertex]) : z + reach * u});
  }
}

Rational LooseRays::parameter(int a, int b) const {
  const Vec& ub = direction_[b];
  return -CGAL::determinant(ub, origin_[a] - origin_[b]) / CGAL::determinant(ub, direction_[a]);
}

void LooseRays::relate(int a, int b, std::vector<Rational>& meet) {
  const std::size_t c = cell(a, b);
  cross_sign_[c] = static_cast<std::int8_t>(CGAL::sign(CGAL::determinant(direction_[a], direction_[b])));
  base_side_[c] = static_cast<std::int8_t>(CGAL::sign(CGAL::determinant(direction_[a], origin_[b] - origin_[a])));
  if (notch(a) == notch(b) || cross_sign_[c] == 0) return;
  meet[c] = parameter(a, b);
  meet_sign_[c] = static_cast<std::int8_t>(CGAL::sign(meet[c]));
}

std::vector<int> LooseRays::sorted_along(int a, const std::vector<Rational>& meet) {
  std::vector<int> rays;
  for (int b = 0; b < count_; ++b)
    if (notch(a) != notch(b) && cross_sign(a, b) != 0) rays.push_back(b);
  std::sort(rays.begin(), rays.end(), [&](int x, int y) { return meet[cell(a, x)] < meet[cell(a, y)]; });
  int rank = -1;
  for (std::size_t k = 0; k < rays.size(); ++k) {
    if (k == 0 || meet[cell(a, rays[k - 1])] < meet[cell(a, rays[k])]) ++rank;
    key_[cell(a, rays[k])] = rank;
  }
  return rays;
}

void LooseRays::list_loose_points(int a, const std::vector<int>& sorted, const std::vector<Rational>& meet) {
  std::vector<int> points;
  for (int b : sorted) {
    const Rational &s = meet[cell(a, b)], &t = meet[cell(b, a)];
    if (s <= 0 || s >= reach_[a] || t <= 0 || t >= reach_[b]) continue;
    const QPoint x = origin_[a] + s * direction_[a];
    opens_[cell(a, b)] = orient(x, origin_[a], origin_[b]) > 0 ? kOpens : kLoose;
    if (made_at_[cell(b, a)] < 0) {
      made_at_[cell(b, a)] = static_cast<int>(made_.size());
      made_.emplace_back();
    }
    made_at_[cell(a, b)] = made_at_[cell(b, a)];
    points.push_back(b);
    loose_points_ += a < b;
  }
  along_.push_back(std::move(points));
}

ProgramCubic::ProgramCubic(const Polygon& p, P4Test p4_test)
    : Program(p), notch_count_(checked(patterns().notches().size())), rays_(p, patterns()),
      rows_(static_cast<std::size_t>(notch_count_) * static_cast<std::size_t>(notch_count_)), p4_test_(p4_test) {}

void ProgramCubic::report(Counters& counters) const {
  counters["x4_loose_points"] = rays_.loose_points();
  counters["x4_table_entries"] = table_entries_;
  counters["x4_table_witnesses"] = table_witnesses_;
  counters["x4_found"] += table_witnesses_;
  counters["x4_scan_steps"] = scan_steps_;
  counters["x4_p4_tests"] = p4_tests_;
  counters["x4_scans_sharing_an_end"] = scans_sharing_an_end_;
  counters["x4_lookup_steps"] = lookup_steps_;
  counters["x4_chosen"] = chosen_;
  counters["x4_chosen_from_w"] = chosen_from_w_;
  counters["x4_rays_at_vertex"] = rays_.stopped_at_vertices();
  counters["x4_funnel_points"] = funnel_points_;
  counters["x4_funnel_steps"] = funnel_steps_;
  counters["geodesic_chords"] = geodesics_ ? geodesics_->chords() : 0;
  counters["geodesic_trees"] = geodesics_ ? geodesics_->trees() : 0;
  counters["geodesic_faces"] = geodesics_ ? geodesics_->faces_entered() : 0;
  counters["geodesic_tangent_steps"] = geodesics_ ? geodesics_->tangent_steps() : 0;
}

Witness ProgramCubic::entry(int g, int h, int q) const {
  const Row& row = rows_[at(g, h)];
  return row.empty() ? Witness{} : row[static_cast<std::size_t>(q)];
}

int ProgramCubic::checked(std::size_t notches) {
  if (notches > static_cast<std::size_t>(kMaxNotches))
    throw std::invalid_argument("chazelle-dobkin: more than 32767 notches");
  return static_cast<int>(notches);
}

ProgramCubic::PlaceSet::PlaceSet(int size) : size_(size) {
  std::size_t count = static_cast<std::size_t>(std::max(size, 1));
  do {
    count = (count + 63) / 64;
    levels_.emplace_back(count, 0);
  } while (count > 1);
}

void ProgramCubic::PlaceSet::insert(int k) {
  for (auto& level : levels_) {
    level[static_cast<std::size_t>(k >> 6)] |= std::uint64_t{1} << (k & 63);
    k >>= 6;
  }
}

int ProgramCubic::PlaceSet::at_or_before(int k) const {
  for (std::size_t level = 0; level < levels_.size() && k >= 0; ++level, k = (k >> 6) - 1) {
    const std::uint64_t word = levels_[level][static_cast<std::size_t>(k >> 6)] & (~std::uint64_t{0} >> (63 - (k & 63)));
    if (word != 0) return descend(level, (k & ~63) | highest(word), highest);
  }
  return -1;
}

int ProgramCubic::PlaceSet::at_or_after(int k) const {
  for (std::size_t level = 0; level < levels_.size() && static_cast<std::size_t>(k >> 6) < levels_[level].size();
       ++level, k = (k >> 6) + 1) {
    const std::uint64_t word = levels_[level][static_cast<std::size_t>(k >> 6)] & (~std::uint64_t{0} << (k & 63));
    if (word != 0) return descend(level, (k & ~63) | lowest(word), lowest);
  }
  return size_;
}

int ProgramCubic::PlaceSet::descend(std::size_t level, int k, int (*pick)(std::uint64_t)) const {
  while (level-- > 0) k = k * 64 + pick(levels_[level][static_cast<std::size_t>(k)]);
  return k;
}

int ProgramCubic::Walk::first_from(int step) const {
  if (!down_) return inserted_.at_or_after(step);
  const int k = inserted_.at_or_before(size_ - 1 - step);
  return k < 0 ? size_ : size_ - 1 - k;
}

std::optional<X4Choice> ProgramCubic::x4_term(int i, int j, int to_beat) {
  std::optional<X4Choice> found;
  if (S(i + 1, j - 1) + 1 > to_beat) found = lookup(i, j);
  fill(i, j);
  return found;
}

std::optional<X4Choice> ProgramCubic::lookup(int i, int j) {
  const int count = S(i + 1, j - 1) + 1;
  for (int k = i + 1; k < j; ++k) {
    ++lookup_steps_;
    const Witness w = tight(i, j, k) ? entry(k, j, i) : Witness{};
    if (w.inner >= 0) return chosen(count, {i, k, w.inner, j}, w.sides, false);
  }
  for (int l = i + 1; l < j; ++l) {
    ++lookup_steps_;
    const Witness w = tight(i, j, l) ? entry(i, l, j) : Witness{};
    if (w.inner >= 0) return chosen(count, {j, i, w.inner, l}, w.sides, true);
  }
  return std::nullopt;
}

X4Choice ProgramCubic::chosen(int count, const std::array<int, 4>& notches, std::uint8_t sides,
                              bool wrapped) {
  const auto [q, g, m, h] = notches;
  const QPoint x = rays_.point(ray(g, sides, 1), ray(q, sides, 0));
  const QPoint y = rays_.point(ray(h, sides, 3), ray(m, sides, 2));
  ++chosen_;
  chosen_from_w_ += wrapped;
  if (wrapped) return X4Choice{count, m, h, true, y, x};
  return X4Choice{count, g, m, false, x, y};
}

void ProgramCubic::check_x4(const std::array<int, 4>& notches, const QPoint& x, const QPoint& y) {
  if (!is_x4(notches, x, y)) throw std::logic_error("chazelle-dobkin: an X4 witness fails Lemma 9");
}

bool ProgramCubic::is_x4(const std::array<int, 4>& notches, const QPoint& x, const QPoint& y) {
  const auto [q, g, m, h] = notches;
  const QPoint &zq = z(q), &zg = z(g), &zm = z(m), &zh = z(h);
  if (orient(x, zq, zg) <= 0 || orient(x, zg, y) <= 0 || orient(x, y, zq) <= 0) return false;
  if (orient(y, zm, zh) <= 0 || orient(y, zh, x) <= 0 || orient(y, x, zm) <= 0) return false;
  for (int a : {q, g})
    if (!joins(a, x)) return false;
  for (int b : {m, h})
    if (!joins(b, y)) return false;
  for (int a : {q, g})
    for (int b : {m, h})
      if (CGAL::do_intersect(Segment(z(a), x), Segment(z(b), y))) return false;
  return patterns().inside(x, y);
}

bool ProgramCubic::joins(int notch, const QPoint& s) {
  return patterns().resolves(patterns().bare(static_cast<std::size_t>(notch)), s) &&
         patterns().sees(patterns().notches()[static_cast<std::size_t>(notch)], s);
}

void ProgramCubic::fill(int g, int h) {
  if (h - g < 2) return;
  Row row;
  for (int sides = 0; sides < 4; ++sides) scan(g, h, 2 * g + (sides & 1), 2 * h + (sides >> 1), row);
  if (!row.empty()) rows_[at(g, h)] = std::move(row);
}

// The inserts' orders are counting sorts, O(r) per scan: by_at along H (Y's rank, then the ray),
// along_g by the rank along G where their lines cross it (-1, parallel, first).
void ProgramCubic::scan(int g, int h, int G, int H, Row& row) {
  const std::vector<Query> queries = open_queries(g, h, G, H, row);
  if (queries.empty()) return;
  Lists lists(G, H, usable_inserts(g, h, G, H));
  if (lists.inserts.empty()) return;
  const auto item = [&](int k) -> const Insert& { return lists.inserts[static_cast<std::size_t>(k)]; };
  const int size = static_cast<int>(lists.inserts.size());
  std::vector<int> positions(lists.inserts.size());
  for (int k = 0; k < size; ++k) positions[static_cast<std::size_t>(k)] = k;
  const std::size_t range = 2 * static_cast<std::size_t>(notch_count_) + 1;
  const std::vector<int> by_ray = stably_ordered(positions, range, [&](int k) { return static_cast<std::size_t>(item(k).ray); });
  const auto at = [&](int k) { return static_cast<std::size_t>(item(k).at); };
  lists.by_at = stably_ordered(by_ray, range, at);
  lists.below_rank = counts_below(positions, range, at);
  const std::vector<int> along_g =
      stably_ordered(positions, range, [&](int k) { return static_cast<std::size_t>(item(k).along + 1); });
  for (int k = 0; k < size; ++k) lists.place[static_cast<std::size_t>(lists.by_at[static_cast<std::size_t>(k)])] = k;
  if (!rays_.loose(G, H)) scans_sharing_an_end_ += rays_.share_an_end(G, H);
  if (p4_test_ == P4Test::kGeodesics) lists.seen.assign(queries.size(), {-1, -1});
  sweep_forward(queries, lists, along_g, row);
  sweep_backward(queries, lists, along_g, row);
  PlaceSet parallel(size);
  for (int k = 0; k < size; ++k)
    if (rays_.cross_sign(lists.at_place(k).ray, G) == 0) parallel.insert(k);
  for (const Query& q : queries) find_visible(q, lists, parallel, row);
}

std::vector<ProgramCubic::Query> ProgramCubic::open_queries(int g, int h, int G, int H, const Row& row) {
  std::vector<Query> out;
  for (int Q : rays_.along(G)) {
    ++scan_steps_;
    const int q = LooseRays::notch(Q);
    if ((q >= g && q <= h) || (!row.empty() && row[static_cast<std::size_t>(q)].inner >= 0)) continue;
    if (!rays_.opens(Q, G) || rays_.side(H, G, Q) >= 0) continue;
    const int turn = rays_.cross_sign(Q, H);
    if (turn == 0 && rays_.base_side(Q, H) <= 0) continue;
    if (turn > 0 && crosses_before(Q, H, G)) continue;
    ++table_entries_;
    out.push_back({Q, rays_.key(G, Q), static_cast<int>(out.size())});
  }
  return out;
}

std::vector<ProgramCubic::Insert> ProgramCubic::usable_inserts(int g, int h, int G, int H) {
  std::vector<Insert> out;
  for (int M : rays_.along(H)) {
    ++scan_steps_;
    const int m = LooseRays::notch(M);
    if (m <= g || m >= h || !tight(g, h, m)) continue;
    if (!rays_.opens(M, H) || rays_.side(G, H, M) >= 0) continue;
    const int turn = rays_.cross_sign(M, G);
    if (turn == 0 && rays_.base_side(M, G) <= 0) continue;
    if (turn > 0 && crosses_before(M, G, H)) continue;
    out.push_back({M, rays_.key(G, M), rays_.key(H, M)});
  }
  return out;
}

bool ProgramCubic::crosses_before(int A, int B, int C) const {
  return rays_.meet_sign(B, A) >= 0 && rays_.meet_sign(A, B) >= 0 && rays_.key(A, B) <= rays_.key(A, C);
}

void ProgramCubic::sweep_forward(const std::vector<Query>& queries, Lists& lists, const std::vector<int>& along_g,
                                 Row& row) {
  PlaceSet inserted(static_cast<int>(lists.inserts.size()));
  std::size_t next = 0;
  for (const Query& q : queries) {
    for (; next < along_g.size() && lists.inserts[static_cast<std::size_t>(along_g[next])].along < q.along; ++next)
      admit(lists, along_g[next], 1, inserted);
    find_visible(q, lists, inserted, row);
  }
}

void ProgramCubic::sweep_backward(const std::vector<Query>& queries, Lists& lists, const std::vector<int>& along_g,
                                  Row& row) {
  PlaceSet inserted(static_cast<int>(lists.inserts.size()));
  std::size_t next = along_g.size();
  for (auto q = queries.rbegin(); q != queries.rend(); ++q) {
    for (; next > 0 && lists.inserts[static_cast<std::size_t>(along_g[next - 1])].along > q->along; --next)
      admit(lists, along_g[next - 1], -1, inserted);
    find_visible(*q, lists, inserted, row);
  }
}

void ProgramCubic::admit(const Lists& lists, int k, int sign, PlaceSet& inserted) {
  ++scan_steps_;
  if (rays_.cross_sign(lists.inserts[static_cast<std::size_t>(k)].ray, lists.G) == sign)
    inserted.insert(lists.place[static_cast<std::size_t>(k)]);
}

int ProgramCubic::p1_end(const Query& query, const Lists& lists) const {
  const int turn = rays_.cross_sign(query.ray, lists.H);
  const int size = static_cast<int>(lists.inserts.size());
  if (turn == 0) return size;
  const int bound = rays_.key(lists.H, query.ray);
  const auto places_below = [&](int rank) { return lists.below_rank[static_cast<std::size_t>(rank)]; };
  return turn > 0 ? size - places_below(bound + 1) : places_below(bound);
}

void ProgramCubic::find_visible(const Query& query, Lists& lists, const PlaceSet& inserted, Row& row) {
  const int q = LooseRays::notch(query.ray);
  if (inserted.empty() || has_witness(row, q)) return;
  const bool down = rays_.cross_sign(query.ray, lists.H) >= 0;
  const int size = static_cast<int>(lists.inserts.size()), end = p1_end(query, lists);
  const Walk walk(inserted, size, down);
  int found = -1;
  if (p4_test_ == P4Test::kSegmentSearch) {
    const QPoint& x = rays_.loose_point(lists.G, query.ray).exact;
    for (int step = walk.first_from(0); step < end && found < 0; step = walk.first_from(step + 1)) {
      ++scan_steps_;
      ++p4_tests_;
      if (patterns().inside(x, y_at(lists, walk.place(step)).exact)) found = step;
    }
  } else if (walk.first_from(0) < end) {
    const auto [lo, hi] = seen_places(query, lists);
    const int from = down ? size - hi : lo, to = down ? size - lo : hi;  // the steps X sees
    const int first = walk.first_from(from);
    if (first < std::min(to, end)) found = first;
  }
  if (found >= 0) record(row, q, query.ray, lists.G, lists.at_place(walk.place(found)).ray, lists.H);
}

std::array<int, 2> ProgramCubic::seen_places(const Query& query, Lists& lists) {
  std::array<int, 2>& seen = lists.seen[static_cast<std::size_t>(query.index)];
  if (seen[0] >= 0) return seen;
  seen = {0, 0};
  const FilteredPoint& x = rays_.loose_point(lists.G, query.ray);
  const Sight sight = sight_of(x, lists);
  if (sight.angle == 0) return seen;
  const auto view = [&](std::size_t place) {
    ++scan_steps_;
    ++p4_tests_;
    return view_from(x, sight, y_at(lists, static_cast<int>(place)));
  };
  const std::size_t size = lists.inserts.size();
  auto& [lo, hi] = lists.place_guess;
  lo = first_holding(0, size, lo, [&](std::size_t k) { return view(k) != View::kTowardsNotch; });
  hi = first_holding(lo, size, hi, [&](std::size_t k) { return view(k) == View::kTowardsFarEnd; });
  seen = {static_cast<int>(lo), static_cast<int>(hi)};
  return seen;
}

ProgramCubic::Sight ProgramCubic::sight_of(const FilteredPoint& x, Lists& lists) {
  if (lists.funnels[0].points.empty())
    for (int end : {0, 1}) lists.funnels[static_cast<std::size_t>(end)] = funnel(lists.G, LooseRays::terminal(lists.H, end));
  Sight sight;
  for (std::size_t end : {0, 1}) sight.first_met[end] = &first_point_met(lists.funnels[end], x, lists.met_guess[end]);
  sight.angle = orient(x, *sight.first_met[0], *sight.first_met[1]);
  return sight;
}

ProgramCubic::Funnel ProgramCubic::funnel(int G, std::size_t e) {
  geodesics().path(LooseRays::terminal(G, 0), e, from_notch_);
  geodesics().path(LooseRays::terminal(G, 1), e, from_far_end_);
  const std::vector<const FilteredPoint*>&A = from_notch_, &B = from_far_end_;
  std::size_t a = A.size(), b = B.size();
  while (a > 0 && b > 0 && A[a - 1] == B[b - 1]) --a, --b;
  if (a == A.size()) throw std::logic_error("chazelle-dobkin: two geodesics to one point end apart");
  // A[0, a) and B[0, b) come before the apex, where the two geodesics meet.
  const FilteredPoint* apex = A[a];
  int turn = 0;
  while (a > 0 && b > 0 && (turn = orient(*apex, *B[b - 1], *A[a - 1])) == 0) {
    // The geodesics list only their turns: the one passes straight through the point that the other
    // lists last before the apex, which the two therefore share.
    if (CGAL::collinear_are_strictly_ordered_along_line(apex->exact, A[a - 1]->exact, B[b - 1]->exact))
      apex = A[--a];
    else if (CGAL::collinear_are_strictly_ordered_along_line(apex->exact, B[b - 1]->exact, A[a - 1]->exact))
      apex = B[--b];
    else
      throw std::logic_error("chazelle-dobkin: a funnel of geodesics with no angle at its apex");
  }
  Funnel f;
  if (a > 0 && b > 0) {
    const std::vector<const FilteredPoint*>& left = turn > 0 ? A : B;
    f.points.assign(left.begin(), left.begin() + static_cast<std::ptrdiff_t>(turn > 0 ? a : b));
  }
  f.apex = f.points.size();
  f.points.push_back(apex);
  if (a > 0 && b > 0) {
    const std::vector<const FilteredPoint*>& right = turn > 0 ? B : A;
    for (std::size_t k = turn > 0 ? b : a; k-- > 0;) f.points.push_back(right[k]);
  }
  funnel_points_ += static_cast<std::int64_t>(f.points.size());
  return f;
}

const FilteredPoint& ProgramCubic::first_point_met(const Funnel& f, const FilteredPoint& x,
                                                   std::size_t& guess) {
  if (f.points.size() > 1) guess = funnel_tangent(f.points, 0, f.points.size() - 1, f.apex, x, guess, funnel_steps_);
  return *f.points[f.points.size() > 1 ? guess : 0];
}

ProgramCubic::View ProgramCubic::view_from(const FilteredPoint& x, const Sight& sight,
                                           const FilteredPoint& y) {
  const auto& [f1, f2] = sight.first_met;
  if (sight.angle == 0 || orient(x, *f1, y) != sight.angle) return View::kTowardsNotch;
  if (orient(x, y, *f2) != sight.angle) return View::kTowardsFarEnd;
  return View::kSeen;
}

void ProgramCubic::record(Row& row, int q, int Q, int G, int M, int H) {
  if (row.empty()) row.assign(static_cast<std::size_t>(notch_count_), Witness{});
  const auto bit = [](int ray, int shift) { return static_cast<std::uint8_t>((ray & 1) << shift); };
  row[static_cast<std::size_t>(q)] = {static_cast<std::int16_t>(LooseRays::notch(M)),
                                      static_cast<std::uint8_t>(bit(Q, 0) | bit(G, 1) | bit(M, 2) | bit(H, 3))};
  ++table_witnesses_;
}

GeodesicTrees& ProgramCubic::geodesics() {
  if (!geodesics_) geodesics_.emplace(polygon(), rays_.terminals());
  return *geodesics_;
}

}  // namespace pd::cd
