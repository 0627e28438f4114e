#pragma once
// Internal to the audio module: the OpenAL device and context, and the extension functions fetched at run
// time (EFX filters, loopback rendering). The public headers never include OpenAL's.
#include <AL/al.h>
#include <AL/alc.h>
#include <AL/alext.h>
#include <AL/efx.h>

#include <string>

namespace ks::audio::detail {

class AlDevice {
  public:
    AlDevice() = default; // no device: the silent engine
    AlDevice(const AlDevice&) = delete;
    AlDevice& operator=(const AlDevice&) = delete;
    ~AlDevice();

    // Opens the default output device with room for `sources` sources. On failure returns false and says why
    // in `reason` (no sound card, only OpenAL Soft's null output, no context).
    bool open_default(int sources, std::string& reason);
    // Opens an ALC_SOFT_loopback device rendering 16-bit stereo at `sample_rate` (HRTF off, so the output is
    // the same on every machine).
    bool open_loopback(int sample_rate, int sources, std::string& reason);

    bool ok() const { return context_ != nullptr; }
    bool loopback() const { return render_ != nullptr; }
    bool has_efx() const { return gen_filters_ != nullptr; }
    int sample_rate() const { return sample_rate_; }

    // Makes this device's context the current one (several engines may live at once: tests, benchmarks).
    void make_current() const;
    // Loopback only: mixes `frames` frames of interleaved 16-bit stereo.
    void render(short* interleaved_stereo, int frames) const;

    // EFX (only when has_efx()).
    void gen_filters(int n, ALuint* ids) const { gen_filters_(n, ids); }
    void delete_filters(int n, const ALuint* ids) const { delete_filters_(n, ids); }
    void filter_i(ALuint id, ALenum param, ALint value) const { filter_i_(id, param, value); }
    void filter_f(ALuint id, ALenum param, ALfloat value) const { filter_f_(id, param, value); }

  private:
    bool create_context(const ALCint* attributes, std::string& reason);
    void load_efx();
    void close();

    ALCdevice* device_ = nullptr;
    ALCcontext* context_ = nullptr;
    int sample_rate_ = 0;
    LPALCRENDERSAMPLESSOFT render_ = nullptr;
    LPALGENFILTERS gen_filters_ = nullptr;
    LPALDELETEFILTERS delete_filters_ = nullptr;
    LPALFILTERI filter_i_ = nullptr;
    LPALFILTERF filter_f_ = nullptr;
};

} // namespace ks::audio::detail
