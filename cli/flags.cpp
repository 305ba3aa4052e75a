#include "cli/flags.hpp"

#include "formats/input_files.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/suggest.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>

namespace impulse::cli {

namespace {

void add_words(CLI::Option* option, const std::string& words) {
    const std::string& description = option->get_description();
    option->description(description.empty() ? words : description + "; " + words);
}

std::string joined(const std::vector<std::string>& names, const std::string& separator) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : separator) + name;
    return text;
}

// The command `args` names (its first word), if it is one.
const CLI::App* command_named(const CLI::App& app, const std::vector<std::string>& args) {
    if (args.empty()) return nullptr;
    const auto found = app.get_subcommands([&](const CLI::App* sub) { return sub->get_name() == args[0]; });
    return found.empty() ? nullptr : found.front();
}

bool is_number(const std::string& text) {
    char* end = nullptr;
    std::strtod(text.c_str(), &end);
    return !text.empty() && end == text.c_str() + text.size();
}

// "unknown flag" and what was meant: a flag of this command a few letters away, else the commands that have it.
std::string unknown_flag(const CLI::App& app, const CLI::App* command, const std::string& flag) {
    const CLI::App& scope = command ? *command : app;
    std::string text = flag + ": unknown flag";
    if (command) text += " of " + command->get_name();
    if (const auto meant = formats::closest_name(flag, flag_names(scope)))
        return text + " (did you mean " + *meant + "?)";
    std::vector<std::string> owners;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        if (sub != command && sub->get_option_no_throw(flag)) owners.push_back(sub->get_name());
    if (!owners.empty())
        text += " (" + flag + " is a flag of " + joined(owners, ", ") +
                (command ? ")" : "; it comes after the command: impulse-lab " + owners.front() + " ... " + flag + ")");
    return text;
}

}  // namespace

CLI::Option* whole_number(CLI::Option* option, FlagCatalog& catalog, long long lowest, long long highest) {
    const std::string words = "a whole number from " + std::to_string(lowest) + " to " + std::to_string(highest);
    const std::string range = std::to_string(lowest) + " to " + std::to_string(highest);
    // CLI11's Range calls "1x" out of range; this says what is wrong with the text itself.
    option->check(CLI::Validator(
        [lowest, highest, words, range](std::string& text) -> std::string {
            long long value = 0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (text.empty() || error == std::errc::invalid_argument || end != text.data() + text.size())
                return "expected " + words + ", got \"" + text + "\"";
            if (error == std::errc::result_out_of_range || value < lowest || value > highest)
                return "must be from " + range + ", got " + text;
            return {};
        },
        ""));
    option->type_name(option->get_positional() ? "" : "N");
    add_words(option, words);
    catalog.value_words[option] = words;
    return option;
}

CLI::Option* finite_number(CLI::Option* option, FlagCatalog& catalog, double lowest, double highest) {
    const std::string range = formats::number_text(lowest) + " to " + formats::number_text(highest);
    const std::string words = "a number from " + range;
    // CLI11's Range lets NaN through: every comparison with it is false.
    option->check(CLI::Validator(
        [lowest, highest, words, range](std::string& text) -> std::string {
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (text.empty() || end != text.c_str() + text.size())
                return "expected " + words + ", got \"" + text + "\"";
            if (!(value >= lowest && value <= highest)) return "must be from " + range + ", got " + text;
            return {};
        },
        ""));
    option->type_name("NUMBER");
    add_words(option, words);
    catalog.value_words[option] = words;
    return option;
}

CLI::Option* one_of(CLI::Option* option, FlagCatalog& catalog, std::vector<std::string> names,
                    const std::string& value_name) {
    const std::string words = "one of " + joined(names, ", ");
    option->check(CLI::Validator(
        [names, words](std::string& text) -> std::string {
            if (std::find(names.begin(), names.end(), text) != names.end()) return {};
            const auto meant = formats::closest_name(text, names);
            return "must be " + words + ", got \"" + text + "\"" + (meant ? " (did you mean " + *meant + "?)" : "");
        },
        ""));
    option->type_name(value_name);
    add_words(option, words);
    catalog.value_words[option] = words;
    catalog.choices[option] = std::move(names);
    return option;
}

CLI::Option* input_file(CLI::Option* option, FlagCatalog& catalog) {
    option->type_name(option->get_positional() ? "" : "FILE");
    add_words(option, "- for standard input");
    catalog.kinds[option] = ValueKind::input_file;
    return option;
}

CLI::Option* output_file(CLI::Option* option, FlagCatalog& catalog) {
    option->type_name("FILE");
    add_words(option, "- for standard output");
    catalog.kinds[option] = ValueKind::output_file;
    return option;
}

CLI::Option* formatted(CLI::Option* option, FlagCatalog& catalog, const std::string& value_name,
                       const std::string& words, std::function<std::string(const std::string&)> check) {
    option->check(CLI::Validator([check](std::string& text) { return check(text); }, ""));
    option->type_name(value_name);
    add_words(option, words);
    catalog.value_words[option] = words;
    return option;
}

CLI::Option* folder(CLI::Option* option, FlagCatalog& catalog) {
    option->type_name("DIR");
    catalog.kinds[option] = ValueKind::folder;
    return option;
}

std::vector<std::string> flag_names(const CLI::App& command) {
    std::vector<std::string> names;
    for (const CLI::Option* option : command.get_options()) {
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
        for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    }
    return names;
}

std::string parse_error_line(const CLI::App& app, const FlagCatalog& catalog, const std::vector<std::string>& args,
                             const CLI::ParseError& error) {
    const CLI::App* command = command_named(app, args);
    const CLI::App& scope = command ? *command : app;
    const std::string help = command ? "impulse-lab " + command->get_name() + " --help" : "impulse-lab help";
    // A flag the command does not have is the mistake to name first: CLI11 would call it and the word after it
    // "not expected", or complain of something else it caused.
    for (std::size_t i = command ? 1 : 0; i < args.size(); ++i) {
        const std::string& word = args[i];
        if (word == "--") break;
        if (word.size() < 2 || word[0] != '-' || is_number(word)) continue;
        const std::string flag = word.substr(0, word.find('='));
        if (!scope.get_option_no_throw(flag)) return unknown_flag(app, command, flag) + "; see " + help;
    }

    std::string text = error.what();
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && text.back() == ' ') text.pop_back();
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&error)) {
        // "--frames: 1 required N missing": the value is missing.
        const std::string flag = text.substr(0, text.find(':'));
        // CLI11 says the same of a flag given twice ("--frames 2 --frames 3" has one value too many).
        const auto given = std::count_if(args.begin(), args.end(), [&flag](const std::string& word) {
            return word == flag || word.starts_with(flag + "=");
        });
        if (given > 1)
            text = flag + ": given " + std::to_string(given) + " times; it takes one value, give it once";
        else if (const CLI::Option* option = scope.get_option_no_throw(flag)) {
            const auto words = catalog.value_words.find(option);
            const std::string name = option->get_type_name().empty() ? "a value" : option->get_type_name();
            text = flag + ": needs a value: " + (words != catalog.value_words.end() ? words->second : name);
        }
    } else if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
        // "The following arguments were not expected: b a" (CLI11 lists them last first).
        const std::size_t colon = text.find(": ");
        std::vector<std::string> extras;
        for (std::size_t at = colon + 2; colon != std::string::npos && at < text.size();) {
            const std::size_t space = std::min(text.find(' ', at), text.size());
            extras.insert(extras.begin(), text.substr(at, space - at));
            at = space + 1;
        }
        text =
            std::string(extras.size() == 1 ? "unexpected argument: " : "unexpected arguments: ") + joined(extras, " ");
        if (command) text = command->get_name() + ": " + text;
    }
    return text + "; see " + help;
}

void check_standard_streams(const CLI::App& command, const FlagCatalog& catalog) {
    std::string reader, writer;  // the first argument given as "-" in each direction
    for (const CLI::Option* option : command.get_options()) {
        const auto kind = catalog.kinds.find(option);
        if (kind == catalog.kinds.end()) continue;
        const std::string name = option->get_name(false, true);
        for (const std::string& value : option->results()) {
            if (value != formats::standard_stream) continue;
            switch (kind->second) {
                case ValueKind::folder:
                    throw formats::InputError(name, "is a folder, so it cannot be standard input or output (\"-\")");
                case ValueKind::input_file:
                    if (!reader.empty())
                        throw formats::InputError(name, "standard input (\"-\") is already read for " + reader +
                                                            "; only one file can come from it");
                    reader = name;
                    break;
                case ValueKind::output_file:
                    if (!writer.empty())
                        throw formats::InputError(name, "standard output (\"-\") already carries " + writer +
                                                            "; only one output can go there");
                    writer = name;
                    break;
                case ValueKind::other:
                    break;
            }
        }
    }
}

namespace {

// "  --frames N                  Frames to simulate ...": CLI11's layout, which help2man reads as a tagged paragraph.
std::string help_line(const std::string& tag, const std::string& text) {
    constexpr std::size_t column = 30;
    std::string line = "  " + tag;
    line += line.size() + 2 <= column ? std::string(column - line.size(), ' ') : "\n" + std::string(column, ' ');
    return line + text + "\n";
}

std::string option_tag(const CLI::Option* option) {
    if (option->get_positional())
        return option->get_name(true) +
               (option->get_expected_max() == CLI::detail::expected_max_vector_size ? " ..." : "");
    std::vector<std::string> names;
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    std::string tag = joined(names, ", ");
    if (option->get_type_size() != 0 && !option->get_type_name().empty()) tag += " " + option->get_type_name();
    if (option->get_type_size() != 0 && option->get_expected_max() == CLI::detail::expected_max_vector_size)
        tag += " ...";
    return tag;
}

std::string indented(const std::string& text, const std::string& indent) {
    std::string result;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        result += indent + text.substr(at, end - at) + "\n";
        at = end + 1;
    }
    return result;
}

}  // namespace

std::string help_all_text(const CLI::App& app, const std::string& introduction,
                          const std::vector<HelpSection>& sections) {
    std::string text = app.get_description() + "\nUsage: impulse-lab COMMAND [OPTIONS] [ARGUMENTS]\n\n" + introduction +
                       "\n\nOptions:\n";
    for (const CLI::Option* option : app.get_options())
        text += help_line(option_tag(option), option->get_description());
    text += "\n*Commands*\n";
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
        std::string usage = "impulse-lab " + sub->get_name();
        bool has_options = false;
        for (const CLI::Option* option : sub->get_options())
            if (!option->get_positional() && option->get_lnames() != std::vector<std::string>{"help"})
                has_options = true;
        if (has_options) usage += " [OPTIONS]";
        for (const CLI::Option* option : sub->get_options())
            if (option->get_positional()) {
                const std::string tag = option_tag(option);
                usage += " " + (option->get_required() ? tag : "[" + tag + "]");
            }
        // An example line becomes its own paragraph, "  $ impulse-lab ...", which help2man sets as code.
        std::string description = sub->get_description(), example;
        if (const std::size_t at = description.find("Example: "); at != std::string::npos) {
            example = description.substr(at + 9);
            description.erase(at);
            while (!description.empty() && description.back() == '\n') description.pop_back();
        }
        text += usage + ":\n" + indented(description, "  ") + "\n";
        if (!example.empty()) text += "  $ " + example + "\n\n";
        for (const CLI::Option* option : sub->get_options())
            if (option->get_lnames() != std::vector<std::string>{"help"})
                text += help_line(option_tag(option), option->get_description());
        text += "\n";
    }
    for (const HelpSection& section : sections) {
        text += "*" + section.name + "*\n";
        for (const auto& [tag, entry] : section.entries) text += help_line(tag, entry);
        text += "\n";
    }
    return text;
}

std::string bash_completion(const CLI::App& app, const FlagCatalog& catalog) {
    const auto words = [](const std::vector<std::string>& list) { return joined(list, " "); };
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        commands.push_back(sub->get_name());

    std::string script =
        "# bash completion for impulse-lab. Generated by `impulse-lab completion bash` from the program's own\n"
        "# commands and flags; install as share/bash-completion/completions/impulse-lab, or source it.\n"
        "_impulse_lab() {\n"
        "    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]} command= i\n"
        "    COMPREPLY=()\n"
        "    for ((i = 1; i < COMP_CWORD; i++)); do\n"
        "        case ${COMP_WORDS[i]} in -*) ;; *) command=${COMP_WORDS[i]}; break ;; esac\n"
        "    done\n"
        "    if [[ -z $command ]]; then\n"
        "        COMPREPLY=($(compgen -W '" +
        words(commands) + " " + words(flag_names(app)) +
        "' -- \"$cur\"))\n"
        "        return\n"
        "    fi\n"
        "    local flags= values= list= positional= positional_list=\n"
        "    case $command in\n";
    // What a flag's value, or a positional argument, is completed with: names (words), files, folders, or nothing.
    const auto completion_of = [&catalog](const CLI::Option* option, const std::string& list) -> std::string {
        const auto choices = catalog.choices.find(option);
        if (choices != catalog.choices.end()) return "words " + list + "='" + joined(choices->second, " ") + "'";
        const auto kind = catalog.kinds.find(option);
        if (kind == catalog.kinds.end()) return "none";
        return kind->second == ValueKind::folder ? "dir" : "file";
    };
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
        script += "    " + sub->get_name() + ")\n";
        script += "        flags='" + words(flag_names(*sub)) + "'\n";
        std::string cases, positional;
        for (const CLI::Option* option : sub->get_options()) {
            if (option->get_positional()) {
                // Every positional of a command is of one kind (files, or the names of one choice).
                const std::string what = completion_of(option, "positional_list");
                if (what != "none" && positional.empty()) positional = "        positional=" + what + "\n";
                continue;
            }
            if (option->get_expected_max() == 0) continue;  // a flag without a value
            std::vector<std::string> names;
            for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
            cases += "            " + joined(names, "|") + ") values=" + completion_of(option, "list") + " ;;\n";
        }
        script += positional;
        if (!cases.empty()) script += "        case $prev in\n" + cases + "        esac\n";
        script += "        ;;\n";
    }
    script +=
        "    esac\n"
        "    [[ $values == none ]] && return\n"
        "    if [[ -z $values ]]; then\n"
        "        if [[ $cur == -* ]]; then\n"
        "            COMPREPLY=($(compgen -W \"$flags\" -- \"$cur\"))\n"
        "            return\n"
        "        fi\n"
        "        values=$positional list=$positional_list\n"
        "    fi\n"
        "    case $values in\n"
        "    words) COMPREPLY=($(compgen -W \"$list\" -- \"$cur\")) ;;\n"
        "    file | dir)\n"
        "        compopt -o filenames 2>/dev/null || true\n"
        "        local IFS=$'\\n' option=-f\n"
        "        [[ $values == dir ]] && option=-d\n"
        "        COMPREPLY=($(compgen $option -- \"$cur\"))\n"
        "        ;;\n"
        "    esac\n"
        "}\n"
        "complete -F _impulse_lab impulse-lab\n";
    return script;
}

}  // namespace impulse::cli
