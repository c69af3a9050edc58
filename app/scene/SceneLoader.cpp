#include "scene/SceneLoader.h"

#include <deque>
#include <exception>
#include <filesystem>

namespace fm::app {
namespace {

// Recently loaded scenes, shared by every loader in the process (scenes are read-only).
class RecentScenes {
  public:
    std::shared_ptr<LoadedScene> find(const std::string& key) {
        std::lock_guard lock(mutex_);
        for (const auto& [k, scene] : entries_)
            if (k == key) return scene;
        return nullptr;
    }
    void add(const std::string& key, std::shared_ptr<LoadedScene> scene) {
        constexpr std::size_t kKeptScenes = 2;  // bounded: a large CT can take GBs
        std::lock_guard lock(mutex_);
        entries_.emplace_front(key, std::move(scene));
        if (entries_.size() > kKeptScenes) entries_.pop_back();
    }

  private:
    std::mutex mutex_;
    std::deque<std::pair<std::string, std::shared_ptr<LoadedScene>>> entries_;
};

RecentScenes& recentScenes() {
    static RecentScenes scenes;
    return scenes;
}

}  // namespace

SceneLoader::~SceneLoader() {
    {
        std::lock_guard lock(mutex_);
        queued_.reset();
    }
    if (worker_.joinable()) worker_.join();
}

void SceneLoader::start(const std::string& spec) {
    std::lock_guard lock(mutex_);
    if (busy_ || finished_) {
        queued_ = spec;
        return;
    }
    launch(spec);
}

std::string sceneCacheKey(const std::string& spec) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path path(spec);
    if (!fs::exists(path, ec)) return spec;  // phantoms (and missing files: never cached)
    std::string key = spec;
    const auto time = fs::last_write_time(path, ec);
    if (!ec) key += "|t" + std::to_string(time.time_since_epoch().count());
    if (fs::is_regular_file(path, ec)) key += "|s" + std::to_string(fs::file_size(path, ec));
    return key;
}

void SceneLoader::launch(const std::string& spec) {
    if (worker_.joinable()) worker_.join();  // the previous worker has finished: busy_ is false
    const std::string key = sceneCacheKey(spec);
    if (auto scene = recentScenes().find(key)) {
        finished_ = Result{spec, std::move(scene), {}};
        return;
    }
    busy_ = true;
    spec_ = spec;
    stage_ = "starting";
    fraction_ = 0.0f;
    started_ = std::chrono::steady_clock::now();
    worker_ = std::thread([this, spec] {
        Result result{spec, nullptr, {}};
        try {
            result.scene = buildScene(spec, [this](const std::string& stage, float fraction) {
                std::lock_guard lock(mutex_);
                stage_ = stage;
                fraction_ = fraction;
            });
        } catch (const std::exception& e) {
            result.error = e.what();
        } catch (...) {
            result.error = "unknown error while loading " + spec;
        }
        std::lock_guard lock(mutex_);
        if (result.scene) recentScenes().add(sceneCacheKey(spec), result.scene);
        finished_ = std::move(result);
        busy_ = false;
    });
}

SceneLoader::Progress SceneLoader::progress() const {
    std::lock_guard lock(mutex_);
    Progress p;
    p.busy = busy_ || queued_.has_value();
    p.spec = busy_ ? spec_ : queued_.value_or(spec_);
    p.stage = busy_ ? stage_ : "queued";
    p.fraction = busy_ ? fraction_ : 0.0f;
    p.elapsedSeconds =
        busy_ ? std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count()
              : 0.0;
    return p;
}

std::optional<SceneLoader::Result> SceneLoader::poll() {
    std::lock_guard lock(mutex_);
    if (busy_ || !finished_) return std::nullopt;
    std::optional<Result> out = std::move(finished_);
    finished_.reset();
    if (queued_) {
        const std::string next = *queued_;
        queued_.reset();
        launch(next);
    }
    return out;
}

std::optional<SceneLoader::Result> SceneLoader::wait() {
    std::optional<Result> last;
    for (;;) {
        if (auto r = poll()) last = std::move(r);
        {
            std::lock_guard lock(mutex_);
            if (!busy_ && !finished_ && !queued_) break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (worker_.joinable()) worker_.join();
    return last;
}

}  // namespace fm::app
