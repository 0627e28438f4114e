#pragma once
// Gas cylinders: lit by a shot, a character's touch or a nearby blast, they explode a fuse later with radial
// damage (walls shelter), a push, and the fuses of their neighbours, so chains go off one fuse apart.
#include "game/game_core.h"

#include <span>
#include <vector>

namespace ks::game {

class LevelEdit; // live_carry.h
class PlayerSystem;
class RobotSystem;

struct Cylinder {
    int entity_id = 0;
    level::GasCylinderProps props;
    Vec3 centre{0.0f};
    float yaw = 0.0f;
    physics::BodyId body;
    float fuse = -1.0f; // seconds until it explodes; < 0 when not lit
    bool exploded = false;
};

class Explosives {
  public:
    // Blasts hurt and push `player` and `robots`, and robots hear them.
    Explosives(GameCore& core, PlayerSystem& player, RobotSystem& robots);

    // A cylinder's record for its (already built) body; next_index() is its index in cylinders().
    std::uint32_t next_index() const { return static_cast<std::uint32_t>(cylinders_.size()); }
    void add(const Cylinder& cylinder) { cylinders_.push_back(cylinder); }

    // Fuses burn in index order.
    void update(float dt);
    void explode(std::size_t index);
    // A character touched it: it explodes at the next step's fuse check.
    void touched(std::size_t index);
    // The live play-test's rebuild (live_carry.h): cylinders the edit kept keep their fuse, or stay gone;
    // returns how many.
    int carry_from(const Explosives& previous, const LevelEdit& edit);
    std::span<const Cylinder> cylinders() const { return cylinders_; }

  private:
    GameCore& core_;
    PlayerSystem& player_;
    RobotSystem& robots_;
    std::vector<Cylinder> cylinders_;
};

} // namespace ks::game
