#include "audio/al_device.h"

#include <cstring>

namespace ks::audio::detail {
namespace {

// OpenAL Soft's fallback backend: it "plays" into nothing while running a mixer thread; treat it as no
// device.
constexpr const char* kNullBackendName = "No Output";

template <class F>
F proc(const char* name) {
    return reinterpret_cast<F>(alGetProcAddress(name));
}

} // namespace

AlDevice::~AlDevice() {
    close();
}

void AlDevice::close() {
    if (context_) {
        if (alcGetCurrentContext() == context_) alcMakeContextCurrent(nullptr);
        alcDestroyContext(context_);
        context_ = nullptr;
    }
    if (device_) {
        alcCloseDevice(device_);
        device_ = nullptr;
    }
    render_ = nullptr;
    gen_filters_ = nullptr;
}

bool AlDevice::create_context(const ALCint* attributes, std::string& reason) {
    context_ = alcCreateContext(device_, attributes);
    if (!context_) {
        reason = "cannot create a context (ALC error " + std::to_string(alcGetError(device_)) + ")";
        close();
        return false;
    }
    make_current();
    ALCint frequency = 0;
    alcGetIntegerv(device_, ALC_FREQUENCY, 1, &frequency);
    if (frequency > 0) sample_rate_ = frequency;
    // The engine applies distance attenuation itself (attenuation.h); OpenAL only pans by direction.
    alDistanceModel(AL_NONE);
    load_efx();
    return true;
}

void AlDevice::load_efx() {
    if (!alcIsExtensionPresent(device_, "ALC_EXT_EFX")) return;
    auto gen = proc<LPALGENFILTERS>("alGenFilters");
    auto del = proc<LPALDELETEFILTERS>("alDeleteFilters");
    auto fi = proc<LPALFILTERI>("alFilteri");
    auto ff = proc<LPALFILTERF>("alFilterf");
    if (!gen || !del || !fi || !ff) return;
    gen_filters_ = gen;
    delete_filters_ = del;
    filter_i_ = fi;
    filter_f_ = ff;
}

bool AlDevice::open_default(int sources, std::string& reason) {
    device_ = alcOpenDevice(nullptr);
    if (!device_) {
        reason = "no default device could be opened";
        return false;
    }
    const ALCchar* name = alcGetString(device_, ALC_DEVICE_SPECIFIER);
    if (name && std::strcmp(name, kNullBackendName) == 0) {
        reason = "only OpenAL Soft's null output is available";
        close();
        return false;
    }
    // The output limiter: many sounds at once (a volley and an explosion) are compressed instead of clipping.
    const ALCint attributes[] = {
        ALC_MONO_SOURCES, sources, ALC_STEREO_SOURCES, sources, ALC_OUTPUT_LIMITER_SOFT, ALC_TRUE, 0};
    return create_context(attributes, reason);
}

bool AlDevice::open_loopback(int sample_rate, int sources, std::string& reason) {
    if (!alcIsExtensionPresent(nullptr, "ALC_SOFT_loopback")) {
        reason = "OpenAL has no ALC_SOFT_loopback extension";
        return false;
    }
    auto open = reinterpret_cast<LPALCLOOPBACKOPENDEVICESOFT>(
        alcGetProcAddress(nullptr, "alcLoopbackOpenDeviceSOFT"));
    auto supported = reinterpret_cast<LPALCISRENDERFORMATSUPPORTEDSOFT>(
        alcGetProcAddress(nullptr, "alcIsRenderFormatSupportedSOFT"));
    auto render =
        reinterpret_cast<LPALCRENDERSAMPLESSOFT>(alcGetProcAddress(nullptr, "alcRenderSamplesSOFT"));
    if (!open || !supported || !render) {
        reason = "the ALC_SOFT_loopback functions are missing";
        return false;
    }
    device_ = open(nullptr);
    if (!device_) {
        reason = "cannot open a loopback device";
        return false;
    }
    if (!supported(device_, sample_rate, ALC_STEREO_SOFT, ALC_SHORT_SOFT)) {
        reason = "the loopback device cannot render 16-bit stereo at " + std::to_string(sample_rate) + " Hz";
        close();
        return false;
    }
    const ALCint attributes[] = {ALC_FORMAT_CHANNELS_SOFT,
                                 ALC_STEREO_SOFT,
                                 ALC_FORMAT_TYPE_SOFT,
                                 ALC_SHORT_SOFT,
                                 ALC_FREQUENCY,
                                 sample_rate,
                                 ALC_HRTF_SOFT,
                                 ALC_FALSE,
                                 ALC_MONO_SOURCES,
                                 sources,
                                 ALC_STEREO_SOURCES,
                                 sources,
                                 ALC_OUTPUT_LIMITER_SOFT,
                                 ALC_TRUE,
                                 0};
    sample_rate_ = sample_rate;
    if (!create_context(attributes, reason)) return false;
    render_ = render;
    return true;
}

void AlDevice::make_current() const {
    if (context_ && alcGetCurrentContext() != context_) alcMakeContextCurrent(context_);
}

void AlDevice::render(short* interleaved_stereo, int frames) const {
    make_current();
    render_(device_, interleaved_stereo, frames);
}

} // namespace ks::audio::detail
