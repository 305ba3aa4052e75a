#include "cli/outputs.hpp"

#include "formats/input_files.hpp"
#include "formats/atomic_file.hpp"
#include "formats/input_error.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sys/stat.h>
#include <unistd.h>

namespace impulse::cli {

bool is_terminal(const std::ostream& stream) {
    if (&stream == &std::cout) return ::isatty(STDOUT_FILENO) == 1;
    if (&stream == &std::cerr) return ::isatty(STDERR_FILENO) == 1;
    return false;
}

namespace {

// What makes two paths one file; empty for what is never the same as anything.
std::string identity_of(const std::string& path) {
    if (path.empty() || path == formats::standard_stream) return {};
    struct stat info {};
    if (::stat(path.c_str(), &info) == 0) {
        if (S_ISCHR(info.st_mode)) return {};
        return std::to_string(info.st_dev) + ":" + std::to_string(info.st_ino);
    }
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::weakly_canonical(std::filesystem::absolute(path), error);
    return "path:" + (error ? std::filesystem::absolute(path).lexically_normal() : absolute).string();
}

}  // namespace

void DistinctFiles::input(std::string what, const std::string& path) {
    named_.push_back({std::move(what), path, identity_of(path), false});
}

void DistinctFiles::output(std::string what, const std::string& path) {
    const std::string identity = identity_of(path);
    if (!identity.empty())
        for (const Named& n : named_) {
            if (n.identity != identity) continue;
            if (!n.output)
                throw formats::InputError(what, "'" + path + "' is " + n.what +
                                                    ", which this command reads: writing it would replace it; "
                                                    "choose another file");
            throw formats::InputError(what, "'" + path + "' is also " + n.what +
                                                "'s file: one output would replace the other; choose another file");
        }
    named_.push_back({std::move(what), path, identity, true});
}

bool names_standard_output(const std::string& path, const std::ostream& out) {
    if (path == formats::standard_stream) return true;
    if (&out != &std::cout) return false;
    struct stat named {
    }, standard{};
    return ::stat(path.c_str(), &named) == 0 && ::fstat(STDOUT_FILENO, &standard) == 0 &&
           named.st_dev == standard.st_dev && named.st_ino == standard.st_ino;
}

void Outputs::add(std::string_view flag, const std::optional<std::string>& path) {
    if (!path) return;
    const bool standard = names_standard_output(*path, out_);
    if (standard) {
        const auto first = std::find_if(named_.begin(), named_.end(), [](const Named& n) { return n.standard_output; });
        if (first != named_.end())
            throw formats::InputError(
                std::string(flag), "standard output already carries " + first->flag + "; only one output can go there");
        to_standard_output_ = true;
    } else {
        formats::check_writable(*path, flag);
    }
    named_.push_back({std::string(flag), *path, standard});
}

bool Outputs::to_standard_output(std::string_view flag) const {
    return std::any_of(named_.begin(), named_.end(),
                       [flag](const Named& n) { return n.flag == flag && n.standard_output; });
}

void Outputs::write(const std::vector<Text>& texts) const {
    const auto named = [this](std::string_view flag) -> const Named* {
        const auto found =
            std::find_if(named_.begin(), named_.end(), [flag](const Named& n) { return n.flag == flag; });
        return found == named_.end() ? nullptr : &*found;
    };
    std::string_view standard_text;
    bool standard = false;
    {
        const formats::HeldInterruptions held;
        std::vector<formats::StagedFile> files;
        for (const Text& t : texts) {
            const Named* n = named(t.flag);
            if (!n) continue;
            if (n->standard_output) {
                standard_text = t.text;
                standard = true;
            } else {
                files.emplace_back(n->path, t.text, n->flag);
            }
        }
        for (formats::StagedFile& f : files) f.commit();
    }
    if (standard) out_.write(standard_text.data(), static_cast<std::streamsize>(standard_text.size())).flush();
}

void StreamedOutput::append(std::string_view text) {
    if (file_) file_->append(text);
    if (standard_) standard_->append(text);
}

void StreamedOutput::append(const formats::Spool& spool) {
    if (file_) file_->append(spool);
    if (standard_) standard_->append(spool);
}

std::optional<StreamedOutput> Outputs::stream(std::string_view flag) const {
    const auto found = std::find_if(named_.begin(), named_.end(), [flag](const Named& n) { return n.flag == flag; });
    if (found == named_.end()) return std::nullopt;
    const bool standard = found->standard_output;
    std::optional<StreamedOutput> output(std::in_place);
    output->flag_ = found->flag;
    if (standard)
        output->standard_ = std::make_unique<formats::Spool>(std::filesystem::temp_directory_path() / "stdout");
    else
        output->file_.emplace(found->path, found->flag);
    return output;
}

void Outputs::commit(const std::vector<StreamedOutput*>& outputs) const {
    const formats::Spool* standard = nullptr;
    {
        const formats::HeldInterruptions held;
        for (StreamedOutput* o : outputs) {
            if (!o) continue;
            if (o->file_) o->file_->commit();
            if (o->standard_) standard = o->standard_.get();
        }
    }
    if (standard) standard->copy_to(out_), out_.flush();
}

std::string Outputs::file_of(std::string_view flag) const {
    const auto found = std::find_if(named_.begin(), named_.end(), [flag](const Named& n) { return n.flag == flag; });
    if (found == named_.end() || found->standard_output) return {};
    return found->path;
}

}  // namespace impulse::cli
