// The student's process: the student's object, the chapter's dispatch (grader/remote/<file>.cpp
// built without WORKBOOK_REMOTE_CHECKER) and this loop. It only computes: it reads a call
// from the grader's channel, runs the student's function and writes the raw result back.
// Whatever else it prints goes to stdout/stderr, which the grader shows as the student's
// output and never reads as a verdict.
//
//     <binary> ANSWERS      calls arrive on standard input; ANSWERS is a file (a pipe the
//                           grader passes as /dev/fd/N) that answers are written to
// Standard C++ only.
#include <cstdio>
#include <exception>
#include <string>

#include "remote.hpp"

namespace {

using workbook::remote::Bytes;
using workbook::remote::Header;

bool send(std::FILE* out, std::uint32_t tag, const Bytes& payload) {
    const Header header{workbook::remote::answer_magic, tag, payload.size()};
    return std::fwrite(&header, sizeof header, 1, out) == 1 &&
           (payload.empty() || std::fwrite(payload.data(), 1, payload.size(), out) == payload.size()) &&
           std::fflush(out) == 0;
}

Bytes text(const std::string& message) {
    const std::string cut = message.substr(0, workbook::remote::max_exception_text);
    return Bytes(cut.begin(), cut.end());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fputs("usage: <student process> ANSWERS (calls on standard input)\n", stderr);
        return 64;
    }
    std::FILE* in = stdin;
    std::FILE* out = std::fopen(argv[1], "wb");
    if (in == nullptr || out == nullptr) {
        std::fputs("workbook-server: cannot open the grader's channel\n", stderr);
        return 65;
    }
    for (;;) {
        Header request;
        if (std::fread(&request, sizeof request, 1, in) != 1) return 0;  // the checker is done
        if (request.magic != workbook::remote::request_magic || request.size > workbook::remote::max_payload) return 66;
        Bytes arguments(static_cast<std::size_t>(request.size));
        if (!arguments.empty() && std::fread(arguments.data(), 1, arguments.size(), in) != arguments.size()) return 66;
        Bytes answer;
        std::uint32_t tag = workbook::remote::answer_returned;
        try {
            answer = workbook::remote::serve_chapter(request.tag, arguments);
        } catch (const workbook::remote::ProtocolError&) {
            return 66;
        } catch (const std::exception& error) {
            tag = workbook::remote::answer_threw;
            answer = text(error.what());
        } catch (...) {
            tag = workbook::remote::answer_threw;
            answer = text("an exception that is not a std::exception");
        }
        if (!send(out, tag, answer)) return 0;
    }
}
