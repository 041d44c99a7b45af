/* Minimal libmodbus server for the benchmark, shaped like a K2's map (holding/input
 * registers 0…2147, coils/discrete inputs 0…8511, unit 1). Serves one client at a time.
 *
 *   mb_server tcp PORT   (0 picks a free port)  prints {"tcp":"127.0.0.1:PORT"} when listening
 *   mb_server rtu        opens a pseudo-terminal  prints {"path":"/dev/pts/N"} when ready
 */
#define _DEFAULT_SOURCE
#include <modbus.h>
#include <errno.h>
#include <string.h>
#include <unistd.h>
#include <pty.h>
#include <termios.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s tcp PORT | rtu\n", argv[0]);
        return 2;
    }
    modbus_mapping_t *map = modbus_mapping_new(8512, 8512, 2148, 2148);
    uint8_t req[MODBUS_TCP_MAX_ADU_LENGTH];
    if (strcmp(argv[1], "rtu") == 0) {
        int master, slave;
        char name[256];
        if (openpty(&master, &slave, name, NULL, NULL) != 0) {
            perror("openpty");
            return 1;
        }
        struct termios t;
        tcgetattr(slave, &t);
        cfmakeraw(&t);
        tcsetattr(slave, TCSANOW, &t);
        modbus_t *ctx = modbus_new_rtu(name, 115200, 'N', 8, 1);
        modbus_set_slave(ctx, 1);
        modbus_set_socket(ctx, master); /* serve the master side directly */
        printf("{\"path\":\"%s\"}\n", name);
        fflush(stdout);
        for (;;) {
            int rc = modbus_receive(ctx, req);
            if (rc > 0)
                modbus_reply(ctx, req, rc, map);
            else if (rc == -1 && errno != EMBBADCRC && errno != EMBBADDATA)
                usleep(1000);
        }
    }
    modbus_t *ctx = modbus_new_tcp("127.0.0.1", argc > 2 ? atoi(argv[2]) : 0);
    modbus_set_slave(ctx, 1);
    int server = modbus_tcp_listen(ctx, 1);
    if (server < 0) {
        fprintf(stderr, "listen: %s\n", modbus_strerror(errno));
        return 1;
    }
    struct sockaddr_in a;
    socklen_t len = sizeof a;
    getsockname(server, (struct sockaddr *)&a, &len);
    printf("{\"tcp\":\"127.0.0.1:%d\"}\n", ntohs(a.sin_port));
    fflush(stdout);
    for (;;) {
        int s = modbus_tcp_accept(ctx, &server);
        if (s < 0) continue;
        int one = 1;
        setsockopt(s, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
        for (;;) {
            int rc = modbus_receive(ctx, req);
            if (rc > 0)
                modbus_reply(ctx, req, rc, map);
            else if (rc == -1)
                break;
        }
        close(s);
    }
}
