#include "engine/contact/primitives.hpp"

namespace elbowsim {

const char* to_string(ContactSlot::Part part) {
  switch (part) {
    case ContactSlot::Part::ball: return "ball";
    case ContactSlot::Part::end_a: return "end a";
    case ContactSlot::Part::end_b: return "end b";
    case ContactSlot::Part::interior: return "interior";
  }
  return "?";
}

std::string slot_name(const Model& model, const ContactGeometry& g, int slot) {
  const ContactSlot& s = g.slots[static_cast<std::size_t>(slot)];
  const Primitive& p = g.primitives[static_cast<std::size_t>(s.primitive)];
  std::string name;
  if (p.elbow >= 0) {
    name = model.elbows[static_cast<std::size_t>(p.elbow)].name;
  } else {
    // The index of this primitive among its link's own.
    int first = s.primitive;
    while (first > 0 && g.primitives[first - 1].link == p.link && g.primitives[first - 1].elbow < 0)
      --first;
    const int nth = s.primitive - first;
    name = "link" + std::to_string(p.link) + ".";
    if (model.links[p.link].collision.kind == LinkCollision::Kind::box)
      name += p.is_ball ? "corner" + std::to_string(nth) : "edge" + std::to_string(nth - 8);
    else
      name += s.part == ContactSlot::Part::ball    ? "ball"
              : s.part == ContactSlot::Part::end_a ? "end_a"
              : s.part == ContactSlot::Part::end_b ? "end_b"
                                                   : "interior";
  }
  if (g.boxes > 1) name += "@box" + std::to_string(s.box);
  return name;
}

namespace {

Primitive ball(int link, const Eigen::Vector3d& centre, double radius) {
  Primitive p;
  p.link = link;
  p.a = p.b = centre;
  p.radius = radius;
  return p;
}

Primitive segment(int link, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius) {
  Primitive p = ball(link, a, radius);
  p.b = b;
  p.is_ball = false;
  return p;
}

void add_box(int link, const LinkCollision& c, std::vector<Primitive>& out) {
  const Eigen::Vector3d h = 0.5 * c.size;
  auto corner = [&](int k) {
    return Eigen::Vector3d(c.center.x() + ((k & 1) ? h.x() : -h.x()),
                           c.center.y() + ((k & 2) ? h.y() : -h.y()),
                           c.center.z() + ((k & 4) ? h.z() : -h.z()));
  };
  for (int k = 0; k < 8; ++k) out.push_back(ball(link, corner(k), 0.0));
  // Edges join corners that differ in one bit; their ends are the corners above.
  for (int k = 0; k < 8; ++k)
    for (int bit : {1, 2, 4})
      if (!(k & bit)) {
        Primitive e = segment(link, corner(k), corner(k | bit), 0.0);
        e.end_a = e.end_b = false;
        out.push_back(e);
      }
}

// The point of `link` (link frame) `p` expressed on the previous link, when
// it is that link's joint origin (a point both links share).
bool shared_with_previous(const Model& m, int link, const Eigen::Vector3d& p,
                          Eigen::Vector3d& on_previous) {
  if (link == 0 || !p.isZero(0)) return false;
  on_previous = m.joints[link].origin_position;
  return true;
}

// The balls at capsule ends, with their owners: only the largest ball at a
// point keeps its slots.
void drop_shared_ends(const Model& m, std::vector<Primitive>& prims) {
  struct End {
    int primitive;
    bool is_a;
    int link;
    Eigen::Vector3d point;  // on `link`
    double radius;
  };
  std::vector<End> ends;
  for (int k = 0; k < static_cast<int>(prims.size()); ++k) {
    const Primitive& p = prims[k];
    if (p.is_ball) {
      ends.push_back({k, true, p.link, p.a, p.radius});
    } else {
      if (p.end_a) ends.push_back({k, true, p.link, p.a, p.radius});
      if (p.end_b) ends.push_back({k, false, p.link, p.b, p.radius});
    }
  }
  auto same_place = [&](const End& x, const End& y) {
    if (x.link == y.link) return (x.point - y.point).isZero(1e-12);
    const End& later = x.link > y.link ? x : y;
    const End& earlier = x.link > y.link ? y : x;
    Eigen::Vector3d there;
    return later.link == earlier.link + 1 && shared_with_previous(m, later.link, later.point, there) &&
           (there - earlier.point).isZero(1e-12);
  };
  for (const End& x : ends) {
    if (prims[x.primitive].is_ball) continue;  // balls (elbows, link spheres, corners) keep theirs
    for (const End& y : ends) {
      if (&x == &y || !same_place(x, y)) continue;
      // A larger ball here, or an equal one met first, covers x.
      const bool covered = y.radius > x.radius || (y.radius == x.radius && (prims[y.primitive].is_ball || y.primitive < x.primitive));
      if (!covered) continue;
      (x.is_a ? prims[x.primitive].end_a : prims[x.primitive].end_b) = false;
      break;
    }
  }
}

}  // namespace

ContactGeometry contact_geometry(const Model& model) {
  ContactGeometry g;
  for (int k = 0; k < static_cast<int>(model.elbows.size()); ++k) {
    const Elbow& e = model.elbows[k];
    g.primitives.push_back(ball(e.link, e.point, e.radius));
    g.primitives.back().elbow = k;
  }
  for (int i = 0; i < model.dof; ++i) {
    const Link& link = model.links[i];
    const LinkCollision& c = link.collision;
    switch (c.kind) {
      case LinkCollision::Kind::capsule:
        if (c.radius > 0)
          g.primitives.push_back(c.from == c.to ? ball(i, c.from, c.radius)
                                                : segment(i, c.from, c.to, c.radius));
        else if (link.tip.isZero(0))
          g.primitives.push_back(ball(i, Eigen::Vector3d::Zero(), link.radius));
        else
          g.primitives.push_back(segment(i, Eigen::Vector3d::Zero(), link.tip, link.radius));
        break;
      case LinkCollision::Kind::sphere: g.primitives.push_back(ball(i, c.center, c.radius)); break;
      case LinkCollision::Kind::box: add_box(i, c, g.primitives); break;
      case LinkCollision::Kind::none: break;
    }
  }
  drop_shared_ends(model, g.primitives);
  // A ball at the origin of link 0 sits on joint 0's axis: it never moves, so it
  // cannot land or press (its row would be zero).
  for (Primitive& p : g.primitives)
    if (p.link == 0 && !p.is_ball && p.a.isZero(0)) p.end_a = false;
  g.boxes = static_cast<int>(model.table.size());
  for (int k = 0; k < static_cast<int>(g.primitives.size()); ++k) {
    const Primitive& p = g.primitives[k];
    for (int b = 0; b < static_cast<int>(model.table.size()); ++b) {
      g.first_slot.push_back(static_cast<int>(g.slots.size()));
      if (p.is_ball) {
        g.slots.push_back({k, b, ContactSlot::Part::ball});
        continue;
      }
      if (p.end_a) g.slots.push_back({k, b, ContactSlot::Part::end_a});
      if (p.end_b) g.slots.push_back({k, b, ContactSlot::Part::end_b});
      if (p.interior) g.slots.push_back({k, b, ContactSlot::Part::interior});
    }
  }
  g.first_slot.push_back(static_cast<int>(g.slots.size()));
  return g;
}

}  // namespace elbowsim
