/* sbd_cmd.h - the snowbody commands beyond stl and check (sbd_main.c dispatches). */
#ifndef SBD_CMD_H
#define SBD_CMD_H

/* snowbody snow-post (sbd_cmd_snow.c): argv[1] is "snow-post"; an exit status */
int sbd_cmd_snow_post(int argc, char **argv);

#endif
