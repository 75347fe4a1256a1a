#include "protocol/ops.h"

#include <array>
#include <utility>

namespace fleetmap {
namespace {

constexpr std::array<std::pair<RequestOp, std::string_view>, 13> kRequestOps{{
    {RequestOp::Ready, "Ready"}, {RequestOp::Alive, "Alive"}, {RequestOp::Stopped, "Stopped"},
    {RequestOp::OpAck, "OpAck"}, {RequestOp::SendPos, "SendPos"}, {RequestOp::SendGPS, "SendGPS"},
    {RequestOp::SendImage, "SendImage"}, {RequestOp::GetMap, "GetMap"}, {RequestOp::GetPath, "GetPath"},
    {RequestOp::GetPosIni, "GetPosIni"}, {RequestOp::GetPosEnd, "GetPosEnd"}, {RequestOp::SetObject, "SetObject"},
    {RequestOp::TourEvent, "TourEvent"},
}};

constexpr std::array<std::pair<AnswerOp, std::string_view>, 8> kAnswerOps{{
    {AnswerOp::Start, "Start"}, {AnswerOp::OpAck, "OpAck"}, {AnswerOp::Abort, "Abort"}, {AnswerOp::SetMap, "SetMap"},
    {AnswerOp::SetPath, "SetPath"}, {AnswerOp::SetPosIni, "SetPosIni"}, {AnswerOp::SetPosEnd, "SetPosEnd"},
    {AnswerOp::Error, "Error"},
}};

constexpr std::array<std::pair<ErrorCode, std::string_view>, 12> kErrorCodes{{
    {ErrorCode::UnknownOp, "unknown_op"}, {ErrorCode::BadJson, "bad_json"}, {ErrorCode::BadParams, "bad_params"},
    {ErrorCode::NotYourRobot, "not_your_robot"}, {ErrorCode::NotRegistered, "not_registered"},
    {ErrorCode::PayloadTooLarge, "payload_too_large"}, {ErrorCode::UnknownAnswer, "unknown_answer"},
    {ErrorCode::NoGoal, "no_goal"}, {ErrorCode::NoPose, "no_pose"}, {ErrorCode::NoPath, "no_path"},
    {ErrorCode::NoPlanner, "no_planner"}, {ErrorCode::Internal, "internal"},
}};

template <typename E, size_t N>
std::string_view find_name(const std::array<std::pair<E, std::string_view>, N>& table, E e) {
  for (const auto& [k, v] : table)
    if (k == e) return v;
  return "?";
}

template <typename E, size_t N>
std::optional<E> find_value(const std::array<std::pair<E, std::string_view>, N>& table, std::string_view s) {
  for (const auto& [k, v] : table)
    if (v == s) return k;  // exact, case-sensitive: the protocol spells them one way
  return std::nullopt;
}

}  // namespace

std::string_view name(RequestOp op) { return find_name(kRequestOps, op); }
std::string_view name(AnswerOp op) { return find_name(kAnswerOps, op); }
std::string_view name(ErrorCode code) { return find_name(kErrorCodes, code); }
std::optional<RequestOp> parse_request_op(std::string_view s) { return find_value(kRequestOps, s); }
std::optional<AnswerOp> parse_answer_op(std::string_view s) { return find_value(kAnswerOps, s); }
std::optional<ErrorCode> parse_error_code(std::string_view s) { return find_value(kErrorCodes, s); }

}  // namespace fleetmap
