#pragma once
// The wire between the grader's trusted checker and the process that runs a student's code.
//
// The checker is the chapter's Catch2 tests (public and hidden) linked, instead of the
// student's object, with a stand-in for every function of the chapter's header. A stand-in
// serialises its arguments, sends them to the student's process, waits for the answer and
// returns it (writing back every non-const reference argument, so resolve(RigidBody&, ...)
// changes the caller's bodies as the real one would). The student's process is the student's
// object plus server.cpp: it reads a call, runs the student's function, writes the result.
// So the verdict, the expected values and the feedback never share a process with student
// code, and nothing that process does can reach a score except the numbers it returns.
//
// Values travel as their raw bytes (doubles bit for bit, never as text); both processes run
// on the same machine from the same headers. Only trivially copyable types can travel, which
// every engine value type is (Vector3, RigidBody, Contact, PositionCorrection, double...).
//
// A chapter lists its functions once, in grader/remote/<file>.cpp (see
// docs/adding-a-chapter.md):
//
//     using Remote = workbook::remote::Functions<&resolve, &energy_lost>;
//     WORKBOOK_REMOTE_SERVE(Remote)
//     #if WORKBOOK_REMOTE_CHECKER
//     void resolve(RigidBody& a, RigidBody& b, const Contact& c) { Remote::call<&resolve>(a, b, c); }
//     ...
//     #endif
// Standard C++ only: the channel is two files the grader opens for both sides.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace workbook::remote {

using Bytes = std::vector<unsigned char>;

/// What can travel: trivially copyable values without pointers (a pointer means nothing in
/// the other process).
template <class T>
concept Wire = std::is_trivially_copyable_v<T> && !std::is_pointer_v<T> && !std::is_reference_v<T>;

/// A malformed frame: a bug, or a student process writing into the channel on purpose.
struct ProtocolError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The student's process ended (crash, exit, time or output limit) before it answered. The
/// grader replaces this text with the reason it observed; the marker lets it recognise it.
inline constexpr const char* process_gone_marker = "[workbook-remote: your code's process ended]";

/// Frame headers. A request's tag is the function's index in the chapter's Functions list;
/// an answer's tag says whether the function returned or threw.
inline constexpr std::uint32_t request_magic = 0x51524257u;  // "WBRQ"
inline constexpr std::uint32_t answer_magic = 0x4e414257u;   // "WBAN"
enum AnswerTag : std::uint32_t { answer_returned = 0, answer_threw = 1 };
inline constexpr std::size_t max_payload = 1u << 20;
inline constexpr std::size_t max_exception_text = 400;

struct Header {
    std::uint32_t magic = 0;
    std::uint32_t tag = 0;
    std::uint64_t size = 0;
};

template <Wire T>
void put(Bytes& out, const T& value) {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    out.insert(out.end(), raw, raw + sizeof(T));
}

template <Wire T>
T take(const Bytes& in, std::size_t& at) {
    if (in.size() - at < sizeof(T) || at > in.size()) throw ProtocolError("a value is cut short");
    T value;
    std::memcpy(&value, in.data() + at, sizeof(T));
    at += sizeof(T);
    return value;
}

/// A parameter the function may change: its new value travels back.
template <class A>
inline constexpr bool is_in_out = std::is_lvalue_reference_v<A> && !std::is_const_v<std::remove_reference_t<A>>;

template <class A>
using Value = std::remove_cvref_t<A>;

template <class A>
inline constexpr bool travels = Wire<Value<A>> && !std::is_rvalue_reference_v<A>;

/// The checker's side of the channel: sends one call, returns the answer's payload, throws
/// std::runtime_error when the student's function threw and a process_gone_marker error
/// when the process is gone. Defined in checker_channel.cpp (linked into checkers only).
Bytes call_student(std::uint32_t function, const Bytes& arguments);

/// The student process's side: runs function `function` of the chapter on `arguments`.
/// Defined by WORKBOOK_REMOTE_SERVE in the chapter's file (server builds only).
Bytes serve_chapter(std::uint32_t function, const Bytes& arguments);

template <auto F>
struct Signature {
    static_assert(sizeof(F) == 0, "a remote function must be a plain function pointer, R (*)(A...)");
};

template <class R, class... A, R (*F)(A...)>
struct Signature<F> {
    static_assert((travels<A> && ...), "every parameter must be a trivially copyable value or reference (see Wire)");
    static_assert(std::is_void_v<R> || Wire<R>, "the return type must be void or trivially copyable (see Wire)");

    /// Checker side: forward the call and write back the answer.
    static R call(std::uint32_t function, A... args) {
        Bytes request;
        (put(request, static_cast<const Value<A>&>(args)), ...);
        const Bytes answer = call_student(function, request);
        std::size_t at = 0;
        if constexpr (std::is_void_v<R>) {
            (write_back<A>(answer, at, args), ...);
            finish(answer, at);
        } else {
            R result = take<R>(answer, at);
            (write_back<A>(answer, at, args), ...);
            finish(answer, at);
            return result;
        }
    }

    /// Student side: decode the arguments, call the student's function, encode the result
    /// and every in-out argument, in parameter order.
    static Bytes serve(const Bytes& request) {
        std::size_t at = 0;
        // Braced initialisation evaluates left to right: the arguments are read in order.
        std::tuple<Value<A>...> values{take<Value<A>>(request, at)...};
        finish(request, at);
        Bytes answer;
        if constexpr (std::is_void_v<R>) {
            std::apply(F, values);
        } else {
            put(answer, static_cast<const R&>(std::apply(F, values)));
        }
        encode_in_out(answer, values, std::index_sequence_for<A...>{});
        return answer;
    }

private:
    template <class P>
    static void write_back(const Bytes& answer, std::size_t& at, P& arg) {
        if constexpr (is_in_out<P>) arg = take<Value<P>>(answer, at);
    }

    template <std::size_t... I>
    static void encode_in_out(Bytes& answer, const std::tuple<Value<A>...>& values, std::index_sequence<I...>) {
        ((is_in_out<std::tuple_element_t<I, std::tuple<A...>>> ? put(answer, std::get<I>(values)) : void()), ...);
    }

    static void finish(const Bytes& bytes, std::size_t at) {
        if (at != bytes.size()) throw ProtocolError("a frame has bytes left over");
    }
};

/// One chapter's remote functions, in a fixed order (the order is their number on the wire).
template <auto... Fs>
struct Functions {
    static constexpr std::uint32_t count = sizeof...(Fs);

    template <auto F, auto G>
    static constexpr bool same() {
        if constexpr (std::is_same_v<decltype(F), decltype(G)>) {
            return F == G;
        } else {
            return false;
        }
    }

    template <auto F>
    static constexpr std::uint32_t index_of() {
        std::uint32_t index = 0;
        std::uint32_t found = count;
        ((same<F, Fs>() ? (found = index, ++index) : ++index), ...);
        return found;
    }

    /// The stand-in's body: forward to the student's process.
    template <auto F, class... Given>
    static decltype(auto) call(Given&&... given) {
        static_assert(index_of<F>() < count,
                      "this function has a stand-in but is missing from the chapter's Functions<...> list");
        return Signature<F>::call(index_of<F>(), std::forward<Given>(given)...);
    }

    static Bytes serve(std::uint32_t function, const Bytes& request) {
        Bytes answer;
        bool served = false;
        std::uint32_t index = 0;
        ((index++ == function ? (answer = Signature<Fs>::serve(request), served = true) : false), ...);
        if (!served) throw ProtocolError("no such function");
        return answer;
    }
};

}  // namespace workbook::remote

#if WORKBOOK_REMOTE_CHECKER
#define WORKBOOK_REMOTE_SERVE(list)
#else
/// In the student's process, the dispatch from a function's number to the student's function.
#define WORKBOOK_REMOTE_SERVE(list)                                                                    \
    workbook::remote::Bytes workbook::remote::serve_chapter(std::uint32_t function, const Bytes& arguments) { \
        return list::serve(function, arguments);                                                       \
    }
#endif
