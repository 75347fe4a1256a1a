#pragma once
// RR/SA operation codes (SPEC 5.2, seed 001 tables II-III): the names are the protocol,
// exactly as robots written by others spell them.
#include <optional>
#include <string_view>

namespace fleetmap {

// Robot -> server (rr.op).
enum class RequestOp { Ready, Alive, Stopped, OpAck, SendPos, SendGPS, SendImage, GetMap, GetPath, GetPosIni,
                       GetPosEnd, SetObject,
                       TourEvent };  // TourEvent: docs/protocol.md (an extension to SPEC 5)

// Server -> robot (sa.op).
enum class AnswerOp { Start, OpAck, Abort, SetMap, SetPath, SetPosIni, SetPosEnd, Error };

std::string_view name(RequestOp op);
std::string_view name(AnswerOp op);
std::optional<RequestOp> parse_request_op(std::string_view s);
std::optional<AnswerOp> parse_answer_op(std::string_view s);

// Error codes of an Error answer (SPEC 5.2).
enum class ErrorCode { UnknownOp, BadJson, BadParams, NotYourRobot, NotRegistered, PayloadTooLarge, UnknownAnswer,
                       NoGoal, NoPose, NoPath, NoPlanner, Internal };

std::string_view name(ErrorCode code);
std::optional<ErrorCode> parse_error_code(std::string_view s);

}  // namespace fleetmap
