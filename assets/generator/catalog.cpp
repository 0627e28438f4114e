#include "catalog.h"
#include "sounds.h"

namespace ks::assetgen {

const std::vector<Recipe>& catalog() {
    static const std::vector<Recipe> recipes = [] {
        std::vector<Recipe> list = {
            {"concrete", "wall panels with seams, bolts and stains", make_surface_concrete},
            {"wood", "vertical wooden planks for the dojo walls", make_surface_wood},
            {"tiles", "floor tiles with grout", make_surface_tiles},
            {"ceiling", "ceiling panels with vents", make_surface_ceiling},
            {"metal", "diamond-plate steel", make_surface_metal},
            {"dojo_floor", "tatami mats", make_surface_dojo_floor},
            {"particles", "fire, smoke and spark sprites", make_particles},
            {"robot", "the wheeled enemy robot", make_robot},
            {"rifle", "the player's rifle", make_rifle},
            {"door", "sliding double door", make_door},
            {"floor_light", "standing spotlight", make_floor_light},
            {"top_light", "hanging ceiling lamp", make_top_light},
            {"control_panel", "the simulation control console", make_control_panel},
            {"gas_cylinder", "explosive gas cylinder", make_gas_cylinder},
            {"pickups", "health, ammo and shield pickups", make_pickups},
            {"archive_shelf", "a bookshelf prop (a designer's model in The Archive)", make_archive_shelf},
            {"icons", "application icons of the game and the editor (desktop menus)", make_icons},
        };
        for (const SoundRecipe& sound : sound_recipes())
            list.push_back({sound.name, sound.what, [&sound](Output& out) {
                                return out.sound(sound.name, finish_sound(sound, sound.render()));
                            }});
        return list;
    }();
    return recipes;
}

} // namespace ks::assetgen
