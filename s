{
  "format": "killswitch-level",
  "version": 4,
  "name": "Untitled",
  "settings": {
    "ambient_color": "#8c99b3",
    "ambient_intensity": 0.2,
    "fog_color": "#0d0f14",
    "fog_density": 0.004,
    "sun_direction": [-0.28221625, -0.94072086, -0.18814416],
    "sun_color": "#fff5e6",
    "sun_intensity": 0.1,
    "gravity": -25
  },
  "player_start": {
    "position": [0, 0, 0],
    "yaw": 0
  },
  "next_id": 1,
  "entities": []
}
