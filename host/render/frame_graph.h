// A small frame graph after Filament's: setup declares resources and gets
// typed handles (FrameGraphId<T>); each pass declares, through a Builder, the
// handles it reads and writes; execution resolves them. execute() culls the
// passes that do not contribute to the requested outputs, checks that every
// read was written by an earlier pass (or is an imported resource), and
// records one stage per pass run.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "render/frame_stats.h"
#include "util/cancel.h"

namespace tsis {

class FrameGraph;

// A typed handle to a resource of one frame graph.
template <typename T>
class FrameGraphId {
  public:
    FrameGraphId() = default;
    bool valid() const { return index_ >= 0; }
    int index() const { return index_; }

  private:
    friend class FrameGraph;
    explicit FrameGraphId(int index) : index_(index) {}
    int index_ = -1;
};

// A resource that is state rather than data of its own: a GL target, a
// method's internal table (its handle orders the passes).
struct Marker {};

class FrameGraph {
  public:
    // What a pass reads and writes, declared when it is added.
    class Builder {
      public:
        template <typename T>
        FrameGraphId<T> read(FrameGraphId<T> id) {
            reads_.push_back(id.index());
            return id;
        }
        template <typename T>
        FrameGraphId<T> write(FrameGraphId<T> id) {
            writes_.push_back(id.index());
            return id;
        }

      private:
        friend class FrameGraph;
        std::vector<int> reads_, writes_;
    };

    // What a pass sees while it runs: its declared resources, and where it
    // reports what the frame's stats record for it.
    class Resources {
      public:
        template <typename T>
        const T& read(FrameGraphId<T> id) const {
            return *static_cast<const T*>(graph_.resolve(pass_, id.index(), false));
        }
        template <typename T>
        T& write(FrameGraphId<T> id) const {
            return *static_cast<T*>(graph_.resolve(pass_, id.index(), true));
        }
        // Bytes the pass moved between GL and CL.
        void addBytes(long long bytes) { bytes_ = (bytes_ < 0 ? 0 : bytes_) + bytes; }
        // Device milliseconds (CL events) for a pass whose work the host does
        // not wait for: recorded instead of the host's wall time.
        void setDeviceMs(double ms) { deviceMs_ = ms; }
        FrameStats& stats() const { return graph_.stats(); }

      private:
        friend class FrameGraph;
        Resources(FrameGraph& graph, size_t pass) : graph_(graph), pass_(pass) {}
        FrameGraph& graph_;
        size_t pass_;
        long long bytes_ = -1;
        double deviceMs_ = -1;
    };

    // A resource the graph owns for this frame, starting as `initial`.
    template <typename T>
    FrameGraphId<T> create(const std::string& name, T initial = T{}) {
        auto owned = std::make_shared<T>(std::move(initial));
        T* ptr = owned.get();
        return FrameGraphId<T>(addResource(name, ptr, std::move(owned), false));
    }
    // A resource that lives outside the graph (kept across frames); it counts
    // as written before the first pass.
    template <typename T>
    FrameGraphId<T> import(const std::string& name, T& external) {
        return FrameGraphId<T>(addResource(name, &external, nullptr, true));
    }

    void addPass(std::string name, const std::function<void(Builder&)>& setup,
                 std::function<void(Resources&)> run);

    // Runs the passes needed for `outputs`, in the order they were added,
    // recording each one's stage (its name, milliseconds, bytes) in `stats`.
    // Asks `cancel` (setCancel) before each pass: tsis::Cancelled stops it there.
    template <typename... T>
    void execute(FrameStats& stats, FrameGraphId<T>... outputs) {
        executeIndices(stats, {outputs.index()...});
    }
    // A resource's value outside the passes (after execute()).
    template <typename T>
    T& get(FrameGraphId<T> id) {
        return *static_cast<T*>(resources_.at(static_cast<size_t>(id.index())).value);
    }
    // Whether a pass that execute() runs reads `id`: valid from the start of
    // execute(), so a pass can skip work that nothing will read.
    template <typename T>
    bool isRead(FrameGraphId<T> id) const {
        return id.valid() && needed_.size() > static_cast<size_t>(id.index()) &&
               needed_[static_cast<size_t>(id.index())];
    }
    // Null: never stopped early.
    void setCancel(Cancel* cancel) { cancel_ = cancel; }
    // Names of the passes the last execute() ran (for tests and --stats).
    const std::vector<std::string>& executed() const { return executed_; }
    // The graph of the last execute(), for --stats: every pass in order with
    // the resources it reads and writes and whether it was culled.
    Json describe() const;

  private:
    struct Resource {
        std::string name;
        void* value = nullptr;
        std::shared_ptr<void> owned;
        bool imported = false;
    };
    struct Pass {
        std::string name;
        std::vector<int> reads, writes;
        std::function<void(Resources&)> run;
    };

    int addResource(std::string name, void* value, std::shared_ptr<void> owned, bool imported);
    void executeIndices(FrameStats& stats, const std::vector<int>& outputs);
    void* resolve(size_t pass, int index, bool write) const;
    FrameStats& stats() const { return *stats_; }

    std::vector<Resource> resources_;
    std::vector<Pass> passes_;
    std::vector<bool> needed_, kept_;
    std::vector<std::string> executed_;
    FrameStats* stats_ = nullptr;
    Cancel* cancel_ = nullptr;
};

}  // namespace tsis
