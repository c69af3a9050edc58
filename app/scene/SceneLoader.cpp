#include "scene/SceneLoader.h"

#include <chrono>
#include <deque>
#include <filesystem>
#include <mutex>
#include <thread>

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

void SceneLoader::start(const std::string& spec) {
    if (!job_.idle()) {
        queued_ = spec;  // replaces any queued one; starts when the current result is taken
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
    if (auto scene = recentScenes().find(sceneCacheKey(spec))) {
        job_.finish(Result{spec, std::move(scene), {}});
        return;
    }
    job_.start(
        spec,
        [spec](const JobReport& report) {
            Result result{spec, buildScene(spec, report), {}};
            recentScenes().add(sceneCacheKey(spec), result.scene);
            return result;
        },
        [spec](const std::string& error) {
            return Result{spec, nullptr, error.empty() ? "unknown error while loading " + spec : error};
        });
}

SceneLoader::Progress SceneLoader::progress() const {
    const JobProgress job = job_.progress();
    Progress p;
    p.busy = job.busy || queued_.has_value();
    p.spec = job.busy ? job.what : queued_.value_or(job.what);
    p.stage = job.busy ? job.stage : "queued";
    p.fraction = job.busy ? job.fraction : 0.0f;
    p.elapsedSeconds = job.elapsedSeconds;
    return p;
}

std::optional<SceneLoader::Result> SceneLoader::poll() {
    std::optional<Result> out = job_.poll();
    if (out && queued_) {
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
        if (job_.idle() && !queued_) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    job_.join();
    return last;
}

}  // namespace fm::app
