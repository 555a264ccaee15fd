// rtnetlink requests for CAN interfaces (layout from linux/rtnetlink.h and linux/can/netlink.h):
//   restart    RTM_NEWLINK with IFLA_LINKINFO { kind "can", data { IFLA_CAN_RESTART = 1 } }
//              (what `ip link set IFACE type can restart` sends);
//   bit rate   RTM_GETLINK for the interface; the answer's IFLA_LINKINFO { data {
//              IFLA_CAN_BITTIMING } } holds struct can_bittiming (what `ip -details link show`
//              prints). Unprivileged.
#include <linux/can/netlink.h>
#include <linux/netlink.h>
#include <linux/rtnetlink.h>
#include <net/if.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include "volcomp/hal/linux/socketcan_socket.hpp"

namespace volcomp::hal::socketcan {
namespace {

// Appends netlink attributes to a message buffer, keeping NLMSG/RTA alignment.
class NetlinkMessage {
 public:
  explicit NetlinkMessage(uint16_t type, uint16_t flags) {
    nlmsghdr h{};
    h.nlmsg_type = type;
    h.nlmsg_flags = flags;
    h.nlmsg_seq = 1;
    Append(&h, sizeof h);
  }
  void Append(const void* data, size_t size) {
    const auto* p = static_cast<const uint8_t*>(data);
    buf_.insert(buf_.end(), p, p + size);
    buf_.resize(NLMSG_ALIGN(buf_.size()), 0);
  }
  // Starts a nested or plain attribute; returns its offset for End().
  size_t Begin(uint16_t type) {
    const size_t at = buf_.size();
    rtattr a{};
    a.rta_type = type;
    Append(&a, sizeof a);
    return at;
  }
  void End(size_t at) {
    rtattr a{};
    std::memcpy(&a, buf_.data() + at, sizeof a);
    a.rta_len = static_cast<uint16_t>(buf_.size() - at);
    std::memcpy(buf_.data() + at, &a, sizeof a);
  }
  void Attribute(uint16_t type, const void* data, size_t size) {
    rtattr a{};
    a.rta_type = type;
    a.rta_len = static_cast<uint16_t>(RTA_LENGTH(size));
    Append(&a, sizeof a);  // sizeof(rtattr) == RTA_LENGTH(0): already aligned
    const auto* p = static_cast<const uint8_t*>(data);
    buf_.insert(buf_.end(), p, p + size);
    buf_.resize(NLMSG_ALIGN(buf_.size()), 0);
  }
  std::vector<uint8_t>& Finish() {
    nlmsghdr h{};
    std::memcpy(&h, buf_.data(), sizeof h);
    h.nlmsg_len = static_cast<uint32_t>(buf_.size());
    std::memcpy(buf_.data(), &h, sizeof h);
    return buf_;
  }

 private:
  std::vector<uint8_t> buf_;
};

// Sends `msg` to the kernel and receives one reply into `reply`; the reply's length, or a failure.
Expected<size_t> Exchange(const std::vector<uint8_t>& msg,
                          uint8_t* reply,
                          size_t capacity,
                          const std::string& what) {
  const int fd = ::socket(AF_NETLINK, SOCK_RAW | SOCK_CLOEXEC, NETLINK_ROUTE);
  if (fd < 0) return Fail(Error::kIoError, SocketCanErrorText(what + ": netlink socket", errno));
  sockaddr_nl kernel{};
  kernel.nl_family = AF_NETLINK;
  if (::sendto(fd, msg.data(), msg.size(), 0, reinterpret_cast<sockaddr*>(&kernel), sizeof kernel) <
      0) {
    const int err = errno;
    ::close(fd);
    return Fail(Error::kIoError, SocketCanErrorText(what + ": netlink send", err));
  }
  timeval tv{1, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  const ssize_t n = ::recv(fd, reply, capacity, 0);
  const int recv_err = errno;
  ::close(fd);
  if (n < 0) return Fail(Error::kIoError, SocketCanErrorText(what + ": netlink reply", recv_err));
  return static_cast<size_t>(n);
}

// The payload of the nested attribute `type` inside [data, data + len), or null.
const rtattr* FindAttribute(const void* data, int len, uint16_t type) {
  for (auto* a = static_cast<const rtattr*>(data); RTA_OK(a, len); a = RTA_NEXT(a, len)) {
    if ((a->rta_type & NLA_TYPE_MASK) == type) return a;
  }
  return nullptr;
}

// NLMSG_OK with the remaining length kept signed (NLMSG_NEXT may take it below zero) and compared
// without the macro's signed/unsigned mix.
bool MessageFits(const nlmsghdr* h, int len) {
  return len >= static_cast<int>(sizeof(nlmsghdr)) && h->nlmsg_len >= sizeof(nlmsghdr) &&
         static_cast<int64_t>(h->nlmsg_len) <= len;
}

}  // namespace

Expected<uint32_t> ParseLinkBitrate(const uint8_t* message, size_t size) {
  int len = static_cast<int>(size);
  for (auto* h = reinterpret_cast<const nlmsghdr*>(message); MessageFits(h, len);
       h = NLMSG_NEXT(h, len)) {
    if (h->nlmsg_type == NLMSG_ERROR) {
      const auto* e = static_cast<const nlmsgerr*>(NLMSG_DATA(h));
      return Fail(Error::kIoError, SocketCanErrorText("bit rate query", -e->error));
    }
    if (h->nlmsg_type != RTM_NEWLINK || h->nlmsg_len < NLMSG_LENGTH(sizeof(ifinfomsg))) continue;
    const auto* ifi = static_cast<const ifinfomsg*>(NLMSG_DATA(h));
    const int attrs_len = static_cast<int>(h->nlmsg_len - NLMSG_LENGTH(sizeof(ifinfomsg)));
    const rtattr* info = FindAttribute(IFLA_RTA(ifi), attrs_len, IFLA_LINKINFO);
    const rtattr* data =
        info != nullptr
            ? FindAttribute(RTA_DATA(info), static_cast<int>(RTA_PAYLOAD(info)), IFLA_INFO_DATA)
            : nullptr;
    const rtattr* timing =
        data != nullptr
            ? FindAttribute(RTA_DATA(data), static_cast<int>(RTA_PAYLOAD(data)), IFLA_CAN_BITTIMING)
            : nullptr;
    if (timing == nullptr || RTA_PAYLOAD(timing) < sizeof(uint32_t)) break;
    can_bittiming bt{};
    std::memcpy(&bt, RTA_DATA(timing),
                RTA_PAYLOAD(timing) < sizeof bt ? RTA_PAYLOAD(timing) : sizeof bt);
    if (bt.bitrate == 0) break;  // a CAN interface whose bit rate was never set
    return bt.bitrate;
  }
  return Fail(Error::kNotFound,
              "no bit timing reported (a virtual interface such as vcan, or a "
              "CAN interface without a bit rate)");
}

Expected<uint32_t> ReadCanBitrate(const std::string& iface) {
  const unsigned index = ::if_nametoindex(iface.c_str());
  if (index == 0) return Fail(Error::kNotFound, SocketCanErrorText("'" + iface + "'", errno));
  NetlinkMessage m(RTM_GETLINK, NLM_F_REQUEST);
  ifinfomsg ifi{};
  ifi.ifi_family = AF_UNSPEC;
  ifi.ifi_index = static_cast<int>(index);
  m.Append(&ifi, sizeof ifi);
  alignas(nlmsghdr) uint8_t reply[16384];
  const Expected<size_t> n =
      Exchange(m.Finish(), reply, sizeof reply, "bit rate of '" + iface + "'");
  if (!n.ok()) return Fail(n.error());
  const Expected<uint32_t> rate = ParseLinkBitrate(reply, *n);
  if (!rate.ok()) return Fail(rate.error().code, "'" + iface + "': " + rate.error().message);
  return rate;
}

Expected<void> RequestCanRestart(const std::string& iface) {
  const unsigned index = ::if_nametoindex(iface.c_str());
  if (index == 0) {
    return Fail(Error::kNotFound, SocketCanErrorText("restart '" + iface + "'", errno));
  }
  NetlinkMessage m(RTM_NEWLINK, NLM_F_REQUEST | NLM_F_ACK);
  ifinfomsg ifi{};
  ifi.ifi_family = AF_UNSPEC;
  ifi.ifi_index = static_cast<int>(index);
  m.Append(&ifi, sizeof ifi);
  const size_t linkinfo = m.Begin(IFLA_LINKINFO);
  m.Attribute(IFLA_INFO_KIND, "can", 3);
  const size_t data = m.Begin(IFLA_INFO_DATA);
  const uint32_t one = 1;
  m.Attribute(IFLA_CAN_RESTART, &one, sizeof one);
  m.End(data);
  m.End(linkinfo);
  alignas(nlmsghdr) uint8_t reply[4096];
  const Expected<size_t> n = Exchange(m.Finish(), reply, sizeof reply, "restart");
  if (!n.ok()) return Fail(n.error());
  int len = static_cast<int>(*n);
  for (auto* h = reinterpret_cast<nlmsghdr*>(reply); MessageFits(h, len); h = NLMSG_NEXT(h, len)) {
    if (h->nlmsg_type == NLMSG_ERROR) {
      const auto* e = static_cast<const nlmsgerr*>(NLMSG_DATA(h));
      if (e->error == 0) return Expected<void>::Ok();
      return Fail(Error::kIoError, SocketCanErrorText("restart '" + iface + "'", -e->error));
    }
  }
  return Fail(Error::kIoError,
              "socketcan: restart '" + iface + "': no acknowledgement from the kernel");
}

}  // namespace volcomp::hal::socketcan
