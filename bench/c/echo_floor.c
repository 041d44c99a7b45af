/* The round-trip floor: a 12-byte message echoed back, one in flight, over loopback TCP or
 * a pseudo-terminal pair (a forked child echoes). A Modbus request of one register is 12
 * bytes on TCP; no Modbus stack can beat this figure on the same machine.
 *
 *   echo_floor tcp COUNT SECONDS
 *   echo_floor pty COUNT SECONDS
 */
#define _DEFAULT_SOURCE
#include <string.h>
#include <unistd.h>
#include <signal.h>
#include <pty.h>
#include <termios.h>
#include <fcntl.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include "common.h"

static int read_n(int fd, char *buf, int n) {
    int got = 0;
    while (got < n) {
        int r = read(fd, buf + got, n - got);
        if (r <= 0) return -1;
        got += r;
    }
    return got;
}

static void echo_loop(int fd) {
    char buf[12];
    while (read_n(fd, buf, 12) == 12)
        if (write(fd, buf, 12) != 12) break;
    _exit(0);
}

int main(int argc, char **argv) {
    if (argc < 4) {
        fprintf(stderr, "usage: %s tcp|pty COUNT SECONDS\n", argv[0]);
        return 2;
    }
    long count = atol(argv[2]);
    double secs = atof(argv[3]);
    int fd;
    pid_t child;
    int one = 1;
    if (strcmp(argv[1], "pty") == 0) {
        int master, slave;
        char name[256];
        if (openpty(&master, &slave, name, NULL, NULL) != 0) return 1;
        struct termios t;
        tcgetattr(slave, &t);
        cfmakeraw(&t);
        tcsetattr(slave, TCSANOW, &t);
        child = fork();
        if (child == 0) echo_loop(master);
        fd = open(name, O_RDWR | O_NOCTTY);
    } else {
        int l = socket(AF_INET, SOCK_STREAM, 0);
        struct sockaddr_in a = {.sin_family = AF_INET, .sin_addr.s_addr = htonl(INADDR_LOOPBACK)};
        socklen_t len = sizeof a;
        bind(l, (struct sockaddr *)&a, sizeof a);
        listen(l, 1);
        getsockname(l, (struct sockaddr *)&a, &len);
        child = fork();
        if (child == 0) {
            int s = accept(l, NULL, NULL);
            setsockopt(s, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
            echo_loop(s);
        }
        fd = socket(AF_INET, SOCK_STREAM, 0);
        if (connect(fd, (struct sockaddr *)&a, sizeof a) != 0) return 1;
        setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    }
    char msg[12] = "0123456789A", back[12];
    double *lat = malloc(sizeof(double) * count);
    double start = now_s(), t = start;
    long n = 0;
    while (n < count && t - start < secs) {
        double t0 = now_s();
        if (write(fd, msg, 12) != 12 || read_n(fd, back, 12) != 12) return 1;
        t = now_s();
        lat[n++] = t - t0;
    }
    print_result(lat, n, t - start);
    kill(child, SIGTERM);
    waitpid(child, NULL, 0);
    return 0;
}
