// Bus-off restart through rtnetlink: RTM_NEWLINK with IFLA_LINKINFO { kind "can",
// data { IFLA_CAN_RESTART = 1 } } (the request `ip link set IFACE type can restart` sends; layout
// from linux/rtnetlink.h and linux/can/netlink.h).
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

}  // namespace

std::string RequestCanRestart(const std::string& iface) {
  const unsigned index = ::if_nametoindex(iface.c_str());
  if (index == 0) return SocketCanErrorText("restart '" + iface + "'", errno);
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
  std::vector<uint8_t>& msg = m.Finish();

  const int fd = ::socket(AF_NETLINK, SOCK_RAW | SOCK_CLOEXEC, NETLINK_ROUTE);
  if (fd < 0) return SocketCanErrorText("restart: netlink socket", errno);
  sockaddr_nl kernel{};
  kernel.nl_family = AF_NETLINK;
  if (::sendto(fd, msg.data(), msg.size(), 0, reinterpret_cast<sockaddr*>(&kernel), sizeof kernel) <
      0) {
    const int err = errno;
    ::close(fd);
    return SocketCanErrorText("restart: netlink send", err);
  }
  timeval tv{1, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  alignas(nlmsghdr) uint8_t reply[4096];
  const ssize_t n = ::recv(fd, reply, sizeof reply, 0);
  const int recv_err = errno;
  ::close(fd);
  if (n < 0) return SocketCanErrorText("restart: netlink reply", recv_err);
  int len = static_cast<int>(n);
  for (auto* h = reinterpret_cast<nlmsghdr*>(reply); NLMSG_OK(h, len); h = NLMSG_NEXT(h, len)) {
    if (h->nlmsg_type == NLMSG_ERROR) {
      const auto* e = static_cast<const nlmsgerr*>(NLMSG_DATA(h));
      if (e->error == 0) return "";
      return SocketCanErrorText("restart '" + iface + "'", -e->error);
    }
  }
  return "socketcan: restart '" + iface + "': no acknowledgement from the kernel";
}

}  // namespace volcomp::hal::socketcan
