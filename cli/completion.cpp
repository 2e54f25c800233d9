// Shell completion. `ricochet completion bash|zsh` prints a script for the shell; the script asks the
// program itself what may follow the words typed so far, so candidates are always this build's commands,
// options and values (bench's subcommands only where bench/ is built, every registered kernel and plugin:, a file
// after --plugin):
//
//   ricochet __complete -- WORD...    WORD...: the words after "ricochet", the last one being completed
//
// prints one line saying what the shell should offer, then the candidates:
//   words      followed by the candidates, one per line, each starting with the word being completed
//   files      the shell completes a file name itself
//   dirs       the shell completes a folder name itself
// `__complete` is hidden from the help and from "did you mean". CLI11 2.1 has no completion of its own.
#include <algorithm>
#include <cctype>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/kernel_id.hpp"
#include "ricochet/kernel_spec.hpp"
#include "ricochet_fuzz/campaign.hpp"

namespace ricochet::cli {

namespace {

struct Reply {
    std::string mode = "words";      ///< words, files or dirs
    std::vector<std::string> words;  ///< with mode words: the candidates
};

/// The value set a validator spells in an option's type name: "TEXT:{bash,zsh}" (CLI::IsMember) or
/// "TEXT:failure|all" (our own validators); empty if it spells none.
std::vector<std::string> value_set(const CLI::Option* opt) {
    std::string spec = opt->get_type_name();
    const auto colon = spec.find(':');
    if (colon == std::string::npos) return {};
    spec = spec.substr(colon + 1);
    if (spec.size() >= 2 && spec.front() == '{' && spec.back() == '}') spec = spec.substr(1, spec.size() - 2);
    const char sep = spec.find(',') != std::string::npos ? ',' : '|';
    std::vector<std::string> values;
    std::string value;
    for (std::size_t i = 0; i <= spec.size(); ++i) {
        if (i == spec.size() || spec[i] == sep) {
            if (value.empty()) return {};
            values.push_back(value);
            value.clear();
        } else if (const char c = spec[i]; std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') {
            value += c;
        } else {
            return {};  // not a list of words: a range, a description
        }
    }
    return values.size() >= 2 ? values : std::vector<std::string>{};
}

bool takes_value(const CLI::Option* opt) { return opt->get_type_size_max() > 0; }

/// The shown subcommand called name (not a hidden one), or null.
const CLI::App* find_subcommand(const CLI::App* cmd, const std::string& name) {
    const auto names = command_names(*cmd);
    return std::find(names.begin(), names.end(), name) != names.end() ? cmd->get_subcommand(name) : nullptr;
}

/// What may be an option's value: a set of words, a file, a folder, or nothing to offer (a number, A:B).
Reply value_of(const CLI::Option* opt) {
    Reply r;
    const auto& l = opt->get_lnames();
    const std::string name = l.empty() ? opt->get_name(true) : l.front();
    if (name == "kernel") {
        for (const KernelId k : registered_kernels()) r.words.emplace_back(kernel_name(k));
        // A plug-in's file follows it (kernel_spec.hpp).
        r.words.emplace_back(k_plugin_spec_prefix);
    } else if (name == "plugin") {
        r.mode = "files";
    } else if (name == "target") {
        for (const std::string_view t : fuzz::k_campaign_targets) r.words.emplace_back(t);
    } else if (auto set = value_set(opt); !set.empty()) {
        r.words = std::move(set);
    } else if (name.ends_with("-dir") || name == "out") {
        r.mode = "dirs";
    } else if (name == "output" || name == "junit" || name == "sarif") {
        r.mode = "files";
    }
    return r;
}

/// What may be the command's positional argument number index (a list takes every one from there on).
Reply positional_of(const CLI::App* root, const CLI::App* cmd, std::size_t index) {
    std::vector<const CLI::Option*> positionals;
    for (const CLI::Option* opt : cmd->get_options())
        if (!opt->nonpositional()) positionals.push_back(opt);
    if (positionals.empty()) return {};
    const CLI::Option* opt = positionals[std::min(index, positionals.size() - 1)];
    if (index >= positionals.size() && opt->get_items_expected_max() == 1) return {};
    if (opt->get_name(true) == "COMMAND") return {"words", command_names(*root)};
    if (auto set = value_set(opt); !set.empty()) return {"words", std::move(set)};
    if (opt->get_name(true) == "libfuzzer_flags") return {};
    return {"files", {}};
}

Reply complete(const CLI::App* root, std::vector<std::string> w) {
    if (w.empty()) w.emplace_back();
    // bash splits "--opt=value" into "--opt" "=" "value" (or "--opt" "=" while the value is empty):
    // glue the earlier ones back; the word being completed stays the value alone.
    std::string cur = w.back();
    std::string prefix;  // put before each candidate: "--opt=" when the shell kept "--opt=val" as one word
    std::vector<std::string> before(w.begin(), w.end() - 1);
    if (cur == "=" && !before.empty() && before.back().starts_with("--")) {
        cur.clear();
    } else if (before.size() >= 2 && before.back() == "=" && before[before.size() - 2].starts_with("--")) {
        before.pop_back();
    } else if (cur.starts_with("--") && cur.find('=') != std::string::npos) {
        const auto eq = cur.find('=');
        before.push_back(cur.substr(0, eq));
        prefix = cur.substr(0, eq + 1);
        cur = cur.substr(eq + 1);
    }
    std::vector<std::string> words;
    for (std::size_t i = 0; i < before.size(); ++i) {
        if (before[i] == "=" && i + 1 < before.size() && !words.empty()) {
            words.back() += "=" + before[++i];
            continue;
        }
        words.push_back(before[i]);
    }

    // Walk the words typed: into subcommands, over options and their values, counting positionals.
    const CLI::App* cmd = root;
    const CLI::Option* pending = nullptr;  // an option still waiting for its value
    bool after_dashdash = false;
    std::size_t positionals = 0;
    for (const std::string& word : words) {
        if (pending) {
            pending = nullptr;
        } else if (after_dashdash) {
            ++positionals;
        } else if (word == "--") {
            after_dashdash = true;
        } else if (word.starts_with('-') && word.size() > 1) {
            const CLI::Option* opt = cmd->get_option_no_throw(word.substr(0, word.find('=')));
            if (opt && takes_value(opt) && word.find('=') == std::string::npos) pending = opt;
        } else if (const CLI::App* sub = positionals == 0 ? find_subcommand(cmd, word) : nullptr) {
            cmd = sub;
        } else {
            ++positionals;
        }
    }

    Reply r;
    if (pending) {
        r = value_of(pending);
    } else if (!prefix.empty()) {
        const CLI::Option* opt = cmd->get_option_no_throw(prefix.substr(0, prefix.size() - 1));
        if (opt && takes_value(opt)) r = value_of(opt);
    } else if (cur.starts_with('-') && !after_dashdash) {
        for (const CLI::Option* opt : cmd->get_options()) {
            for (const std::string& l : opt->get_lnames()) r.words.push_back("--" + l);
            for (const std::string& s : opt->get_snames()) r.words.push_back("-" + s);
        }
    } else if (const auto subs = command_names(*cmd); positionals == 0 && !subs.empty()) {
        r.words = subs;
    } else {
        r = positional_of(root, cmd, positionals);
    }
    // Only the candidates that extend what is typed, with the prefix the shell kept.
    std::vector<std::string> kept;
    for (const std::string& c : r.words)
        if (c.starts_with(cur)) kept.push_back(prefix + c);
    r.words = std::move(kept);
    return r;
}

constexpr std::string_view k_bash_script = R"(# bash completion for ricochet, printed by `ricochet completion bash`.
# Load it with: source <(ricochet completion bash), or save it as
# ~/.local/share/bash-completion/completions/ricochet. It asks `ricochet __complete` what may follow.
_ricochet() {
    local IFS=$'\n' cur=${COMP_WORDS[COMP_CWORD]}
    local -a reply
    reply=($("${COMP_WORDS[0]}" __complete -- "${COMP_WORDS[@]:1:COMP_CWORD}" 2>/dev/null)) || return 0
    [[ $cur == = ]] && cur=
    case ${reply[0]} in
        files) compopt -o filenames 2>/dev/null; COMPREPLY=($(compgen -f -- "$cur")) ;;
        dirs)  compopt -o filenames 2>/dev/null; COMPREPLY=($(compgen -d -- "$cur")) ;;
        *)     COMPREPLY=("${reply[@]:1}") ;;
    esac
}
complete -F _ricochet ricochet
)";

constexpr std::string_view k_zsh_script = R"(#compdef ricochet
# zsh completion for ricochet, printed by `ricochet completion zsh`.
# Load it with: source <(ricochet completion zsh) after compinit, or save it as _ricochet in a folder of
# $fpath. It asks `ricochet __complete` what may follow.
_ricochet() {
    local -a reply
    reply=("${(@f)$("${words[1]}" __complete -- "${(@)words[2,CURRENT]}" 2>/dev/null)}")
    case ${reply[1]} in
        files) compset -P '*='; _files ;;
        dirs)  compset -P '*='; _files -/ ;;
        *)     (( ${#reply} > 1 )) && compadd -Q -- "${(@)reply[2,-1]}" ;;
    esac
}
if [[ ${zsh_eval_context[-1]} == loadautofunc ]]; then _ricochet "$@"; else compdef _ricochet ricochet; fi
)";

}  // namespace

void register_completion(CLI::App& app) {
    auto shell = std::make_shared<std::string>();
    CLI::App* sub = app.add_subcommand("completion", "print a shell completion script (bash or zsh) on stdout");
    sub->add_option("SHELL", *shell, "the shell: bash or zsh")->required()->check(CLI::IsMember({"bash", "zsh"}));
    sub->callback([shell] { write_stdout(*shell == "bash" ? k_bash_script : k_zsh_script); });

    // The scripts' question; hidden (no group), every argument passed through unparsed.
    auto words = std::make_shared<std::vector<std::string>>();
    CLI::App* ask = app.add_subcommand("__complete", "");
    ask->group("");
    ask->set_help_flag();
    ask->add_option("WORD", *words, "")->allow_extra_args();
    ask->callback([&app, words] {
        const Reply r = complete(&app, *words);
        std::string out = r.mode + "\n";
        for (const std::string& w : r.words) out += w + "\n";
        write_stdout(out);
    });
}

}  // namespace ricochet::cli
