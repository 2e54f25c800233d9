// Loading plug-in kernels (plugin_loader.hpp): dlopen, the entry, the table's checks, init, registration.
#include "ricochet/plugin_loader.hpp"

#include <dlfcn.h>

#include <array>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <system_error>

#include <fmt/format.h>

#include "base/shown_text.hpp"
#include "kernels/plugin/plugin_table.hpp"
#include "ricochet/from_chars.hpp"
#include "ricochet/plugin_guard.hpp"

namespace ricochet {
namespace detail {
namespace {

std::array<LoadedPlugin, k_max_plugins> g_plugins;
std::size_t g_loaded = 0;
std::mutex g_load_mutex;

/// The environment variable that sets how long one call into a plug-in may take.
constexpr const char* k_timeout_env = "RICOCHET_PLUGIN_TIMEOUT";
/// The longest timeout it may set: a day.
constexpr double k_max_timeout_s = 86400;

/// RICOCHET_PLUGIN_TIMEOUT's seconds (default k_default_plugin_timeout_s), or nothing and why.
std::optional<double> timeout_from_env(std::string* why) {
    const char* env = std::getenv(k_timeout_env);
    if (env == nullptr || *env == '\0') return k_default_plugin_timeout_s;
    const std::string_view text = env;
    double seconds = 0;
    const auto [end, ec] = from_chars_double(text.data(), text.data() + text.size(), seconds);
    if (ec != std::errc{} || end != text.data() + text.size() || !(seconds >= 0 && seconds <= k_max_timeout_s)) {
        *why = fmt::format("{}: '{}' is not a number of seconds from 0 (no limit) to {}", k_timeout_env, shown(text),
                           k_max_timeout_s);
        return std::nullopt;
    }
    return seconds;
}

/// A kernel name: 1 to RICOCHET_PLUGIN_MAX_NAME of A-Z a-z 0-9 - _ . (never a ':', so never a plugin: spec).
bool well_formed_name(std::string_view name) {
    if (name.empty() || name.size() > RICOCHET_PLUGIN_MAX_NAME) return false;
    for (const char c : name)
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.'))
            return false;
    return true;
}

/// The bytes of ricochet_plugin a table must have, of either version: up to and including sweep, the required
/// function.
constexpr std::size_t k_required_bytes = offsetof(ricochet_plugin, sweep) + sizeof(ricochet_plugin::sweep);
/// The most of ricochet_plugin a version-1 table can hold: everything before version 2's first field.
constexpr std::size_t k_version_1_bytes = offsetof(ricochet_plugin, sweep_disc);
/// The oldest ABI version this ricochet loads (RICOCHET_PLUGIN_ABI_VERSION is the newest).
constexpr std::uint32_t k_oldest_abi = 1;

/// True for a table version this ricochet loads: 1 (point balls) or 2 (discs too).
bool spoken(std::uint32_t abi) { return abi >= k_oldest_abi && abi <= RICOCHET_PLUGIN_ABI_VERSION; }

/// Calls every loaded plug-in's destroy when the process ends normally.
void destroy_all() {
    for (std::size_t s = 0; s < g_loaded; ++s) {
        LoadedPlugin& p = g_plugins[s];
        if (p.api.destroy == nullptr) continue;
        const PluginCall call(s, PluginOp::destroy);
        p.api.destroy(p.context);
    }
}

/// Copies table (of the plug-in in slot, as its entry returned it) into p: as much of it as its version and
/// struct_size say it has. Sets abi, size and name (empty when the table has none or its version is not spoken).
void copy_table(std::size_t slot, const ricochet_plugin* table, LoadedPlugin& p, std::uint32_t& abi,
                std::uint32_t& size, std::string& name) {
    // The table is the plug-in's: a bad pointer there is its crash.
    const PluginCall call(slot, PluginOp::entry);
    abi = table->abi_version;
    size = table->struct_size;
    if (spoken(abi) && size >= k_required_bytes) {
        // A version-1 table ends before the disc functions, whatever struct_size it claims.
        const std::size_t known = abi == 1 ? k_version_1_bytes : sizeof(ricochet_plugin);
        std::memcpy(&p.api, table, std::min<std::size_t>(size, known));
        if (p.api.name != nullptr) name.assign(p.api.name, strnlen(p.api.name, RICOCHET_PLUGIN_MAX_NAME + 1));
    }
}

/// The steps after the table is copied, the same for a loaded and a linked-in plug-in: its version, size, name and
/// sweep checked, init run, the kernel registered into slot. where names it in messages ("plug-in PATH", ...),
/// shown its place in reports ("PATH", "linked into this program").
std::optional<KernelId> admit(std::size_t slot, LoadedPlugin p, std::uint32_t abi, std::uint32_t size,
                              const std::string& name, const std::string& where, const std::string& shown_at,
                              std::string* why) {
    const auto fail = [&](std::string message) -> std::optional<KernelId> {
        *why = std::move(message);
        return std::nullopt;
    };
    if (!spoken(abi))
        return fail(fmt::format("{}: its table is for plugin.h ABI version {}, this ricochet speaks versions {} and {} "
                                "(rebuild it against this ricochet's ricochet/plugin.h)",
                                where, abi, k_oldest_abi, RICOCHET_PLUGIN_ABI_VERSION));
    if (size < k_required_bytes)
        return fail(fmt::format("{}: its table says struct_size {}, ABI version {} needs at least {} bytes (set it "
                                "to sizeof(ricochet_plugin))",
                                where, size, abi, k_required_bytes));
    if (p.api.name == nullptr) return fail(fmt::format("{}: its table has no name", where));
    if (!well_formed_name(name))
        return fail(fmt::format("{}: its kernel name '{}' is not 1 to {} of A-Z a-z 0-9 - _ .", where, shown(name),
                                RICOCHET_PLUGIN_MAX_NAME));
    if (const auto taken = parse_kernel(name)) {
        const PluginInfo* other = plugin_info(*taken);
        return fail(fmt::format("{}: its kernel name '{}' is taken, by {}", where, name,
                                other == nullptr      ? std::string("a kernel of ricochet's")
                                : other->path.empty() ? std::string("a kernel linked into this program")
                                                      : fmt::format("the plug-in {}", other->path.string())));
    }
    const std::string named = fmt::format("plug-in kernel '{}' ({})", name, shown_at);
    if (p.api.sweep == nullptr) return fail(fmt::format("{}: no sweep function (plugin.h: it is required)", named));
    guard_name_plugin(slot, name, shown_at);
    if (p.api.init != nullptr) {
        std::int32_t rc = 0;
        {
            const PluginCall call(slot, PluginOp::init);
            rc = p.api.init(&p.context);
        }
        if (rc != 0) return fail(fmt::format("{}: its init function failed (returned {})", named, rc));
    }
    p.info.name = name;
    p.info.frame_step = p.api.step != nullptr;
    p.info.abi_version = abi;
    p.info.discs = p.api.sweep_disc != nullptr;
    p.info.bumpers = p.api.sweep_disc != nullptr && p.api.sweep_disc_bumper != nullptr;
    g_plugins[slot] = std::move(p);
    const auto id = register_kernel(plugin_kernel_ops(slot));
    if (!id) {
        if (g_plugins[slot].api.destroy != nullptr) {
            const PluginCall call(slot, PluginOp::destroy);
            g_plugins[slot].api.destroy(g_plugins[slot].context);
        }
        g_plugins[slot] = LoadedPlugin{};
        return fail(fmt::format("{}: no room in the kernel registry ({} kernels at most)", named, k_max_kernels));
    }
    g_plugins[slot].id = *id;
    if (g_loaded++ == 0) std::atexit(destroy_all);
    return id;
}

/// Loads file (absolute, canonical) into slot: the steps of load_plugin after its checks of the path.
std::optional<KernelId> load_into(std::size_t slot, const std::filesystem::path& file, std::string* why) {
    const std::string where = fmt::format("plug-in {}", file.string());
#if defined(__EMSCRIPTEN__)
    // wasm32 (emscripten): a program built without dynamic linking has no dlopen, and a plug-in would be a wasm
    // side module anyway, not the shared library plugin.h describes.
    (void)slot;
    *why = fmt::format("{}: cannot load it: plug-in kernels need dlopen, which this build (wasm32) does not have", where);
    return std::nullopt;
#endif
    guard_name_plugin(slot, "", file.string());
    void* handle = nullptr;
    {
        const PluginCall call(slot, PluginOp::load);
        handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    }
    if (handle == nullptr) {
        const char* e = dlerror();
        *why = fmt::format("{}: cannot load it: {}", where, e != nullptr ? e : "dlopen failed");
        return std::nullopt;
    }
    // Another path to a file already loaded (a hard link): dlopen hands back the same library.
    for (std::size_t s = 0; s < g_loaded; ++s)
        if (g_plugins[s].handle == handle) {
            dlclose(handle);
            return g_plugins[s].id;
        }
    const auto fail = [&](std::string message) -> std::optional<KernelId> {
        dlclose(handle);
        *why = std::move(message);
        return std::nullopt;
    };
    void* symbol = dlsym(handle, RICOCHET_PLUGIN_ENTRY_SYMBOL);
    if (symbol == nullptr)
        return fail(fmt::format("{}: no symbol {} (a plug-in defines it: see ricochet/plugin.h)", where,
                                RICOCHET_PLUGIN_ENTRY_SYMBOL));
    LoadedPlugin p;
    p.handle = handle;
    p.info.path = file;
    std::uint32_t abi = 0, size = 0;
    std::string name;
    const ricochet_plugin* table = nullptr;
    {
        // The entry is the plug-in's: a crash in it is its crash.
        const PluginCall call(slot, PluginOp::entry);
        const auto entry = reinterpret_cast<ricochet_plugin_entry_fn>(symbol);
        table = entry(RICOCHET_PLUGIN_ABI_VERSION);
        // A version-1 plug-in may serve only the version it was built for: ask it for that one too.
        if (table == nullptr) table = entry(k_oldest_abi);
    }
    if (table == nullptr) return fail(fmt::format("{}: {} returned no table", where, RICOCHET_PLUGIN_ENTRY_SYMBOL));
    copy_table(slot, table, p, abi, size, name);
    std::string refused;
    const auto id = admit(slot, std::move(p), abi, size, name, where, file.string(), &refused);
    if (!id) return fail(std::move(refused));
    return id;
}

}  // namespace

LoadedPlugin& loaded_plugin(std::size_t slot) { return g_plugins[slot]; }

}  // namespace detail

std::optional<KernelId> load_plugin(const std::filesystem::path& file, std::string* error) {
    using namespace detail;
    std::string why;
    const auto refuse = [&](std::string message) -> std::optional<KernelId> {
        if (error != nullptr) *error = std::move(message);
        return std::nullopt;
    };
    std::error_code ec;
    if (file.empty()) return refuse("a plug-in needs a file (plugin:PATH, --plugin PATH)");
    if (!std::filesystem::exists(file, ec))
        return refuse(fmt::format("plug-in {}: no such file", file.string()));
    if (std::filesystem::is_directory(file, ec))
        return refuse(fmt::format("plug-in {}: a folder, not a shared library", file.string()));
    const std::filesystem::path canonical = std::filesystem::canonical(file, ec);
    if (ec) return refuse(fmt::format("plug-in {}: {}", file.string(), ec.message()));
    const std::lock_guard lock(g_load_mutex);
    for (std::size_t s = 0; s < g_loaded; ++s)
        if (g_plugins[s].info.path == canonical) return g_plugins[s].id;
    const auto timeout = timeout_from_env(&why);
    if (!timeout) return refuse(why);
    if (g_loaded == k_max_plugins)
        return refuse(fmt::format("plug-in {}: {} plug-ins are loaded already, the most", canonical.string(), k_max_plugins));
    guard_start(*timeout);
    const auto id = load_into(g_loaded, canonical, &why);
    if (!id) return refuse(why);
    return id;
}

std::optional<KernelId> register_plugin(const ricochet_plugin& table, std::string* error) {
    using namespace detail;
    std::string why;
    const auto refuse = [&](std::string message) -> std::optional<KernelId> {
        if (error != nullptr) *error = std::move(message);
        return std::nullopt;
    };
    const std::lock_guard lock(g_load_mutex);
    for (std::size_t s = 0; s < g_loaded; ++s)
        if (g_plugins[s].table == &table) return g_plugins[s].id;
    const auto timeout = timeout_from_env(&why);
    if (!timeout) return refuse(why);
    if (g_loaded == k_max_plugins)
        return refuse(fmt::format("kernel table at {}: {} plug-ins are registered already, the most",
                                  static_cast<const void*>(&table), k_max_plugins));
    guard_start(*timeout);
    const std::size_t slot = g_loaded;
    constexpr const char* k_linked_in = "linked into this program";
    guard_name_plugin(slot, "", k_linked_in);
    LoadedPlugin p;
    p.table = &table;
    std::uint32_t abi = 0, size = 0;
    std::string name;
    copy_table(slot, &table, p, abi, size, name);
    const std::string where = name.empty() ? std::string("the kernel table linked into this program")
                                           : fmt::format("the kernel table '{}' linked into this program", shown(name));
    const auto id = admit(slot, std::move(p), abi, size, name, where, k_linked_in, &why);
    if (!id) return refuse(why);
    return id;
}

const PluginInfo* plugin_info(KernelId k) {
    using namespace detail;
    for (std::size_t s = 0; s < g_loaded; ++s)
        if (g_plugins[s].id == k) return &g_plugins[s].info;
    return nullptr;
}

}  // namespace ricochet
