// The checker's end of the channel to the student's process (see remote.hpp). The grader
// starts both processes and connects them with two pipes: the checker writes calls to its
// standard output and reads answers from its standard input (its report goes to a file,
// -o). Nothing is opened by name, so a student process that is gone is simply an end of
// file (or a failed write) here, never a wait. Standard C++.
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "remote.hpp"

namespace workbook::remote {

namespace {

class Channel {
public:
    Channel() {
        // Without the grader around, stdout would be a terminal and the calls would go nowhere.
        if (std::getenv("WORKBOOK_REMOTE_CHANNEL") == nullptr)
            throw std::runtime_error("this checker calls the student's functions only when run by the grader");
    }

    Bytes exchange(std::uint32_t function, const Bytes& arguments) {
        // Once the process is gone, every later call of the test case fails the same way.
        if (broken_) gone();
        const Header request{request_magic, function, arguments.size()};
        if (std::fwrite(&request, sizeof request, 1, requests_) != 1 ||
            (!arguments.empty() && std::fwrite(arguments.data(), 1, arguments.size(), requests_) != arguments.size()) ||
            std::fflush(requests_) != 0)
            gone();
        Header answer;
        if (std::fread(&answer, sizeof answer, 1, answers_) != 1) gone();
        if (answer.magic != answer_magic || answer.size > max_payload) {
            broken_ = true;
            throw ProtocolError("your code's process wrote something else than an answer into the grader's channel");
        }
        Bytes payload(static_cast<std::size_t>(answer.size));
        if (!payload.empty() && std::fread(payload.data(), 1, payload.size(), answers_) != payload.size()) gone();
        if (answer.tag == answer_threw) throw std::runtime_error(std::string(payload.begin(), payload.end()));
        if (answer.tag != answer_returned) {
            broken_ = true;
            throw ProtocolError("an answer with an unknown tag");
        }
        return payload;
    }

private:
    [[noreturn]] void gone() {
        broken_ = true;
        throw std::runtime_error(process_gone_marker);
    }

    std::FILE* requests_ = stdout;
    std::FILE* answers_ = stdin;
    bool broken_ = false;
};

}  // namespace

Bytes call_student(std::uint32_t function, const Bytes& arguments) {
    static Channel channel;
    return channel.exchange(function, arguments);
}

}  // namespace workbook::remote
