// test_view.c — `handspring view` (tool/view.c, docs/tool.md): the files it writes exist, have
// the frame count and size asked for, and show the objects where and as they must be (pixels read
// with libpng), and bad options get one error line and exit status 2.
#include <setjmp.h>
#include <stdbool.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>
#include <png.h>

static const char *tool(void) {
	const char *t = getenv("HS_TOOL");
	return t && *t ? t : "build/handspring";
}

// Runs `handspring view ARGS...` with stdout and stderr to /dev/null; its exit status.
static int view(const char *const *args) {
	const char *argv[24];
	int n = 0;
	argv[n++] = tool();
	argv[n++] = "view";
	for (int i = 0; args[i] && n < 23; ++i)
		argv[n++] = args[i];
	argv[n] = NULL;
	fflush(stdout);
	pid_t pid = fork();
	assert_true(pid >= 0);
	if (pid == 0) {
		FILE *null = freopen("/dev/null", "w", stdout);
		null = freopen("/dev/null", "w", stderr);
		(void)null;
		execv(argv[0], (char *const *)argv);
		_exit(127);
	}
	int status = 0;
	assert_int_equal(waitpid(pid, &status, 0), pid);
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static unsigned char *read_all(const char *path, size_t *size) {
	FILE *f = fopen(path, "rb");
	if (!f)
		return NULL;
	fseek(f, 0, SEEK_END);
	long n = ftell(f);
	fseek(f, 0, SEEK_SET);
	unsigned char *buf = malloc((size_t)n + 1);
	assert_non_null(buf);
	assert_int_equal(fread(buf, 1, (size_t)n, f), (size_t)n);
	fclose(f);
	buf[n] = 0;
	*size = (size_t)n;
	return buf;
}

// A GIF's logical screen size and its number of images (frames): the blocks walked one by one.
static int gif_frames(const unsigned char *g, size_t n, int *width, int *height) {
	assert_true(n > 13 && memcmp(g, "GIF89a", 6) == 0);
	*width = g[6] | g[7] << 8;
	*height = g[8] | g[9] << 8;
	size_t p = 13;
	if (g[10] & 0x80) // global colour table
		p += 3u * (1u << ((g[10] & 7) + 1));
	int frames = 0;
	while (p < n && g[p] != 0x3B) {
		if (g[p] == 0x21) { // extension: label, then data sub-blocks
			p += 2;
		} else {
			assert_int_equal(g[p], 0x2C); // image descriptor
			frames++;
			unsigned flags = g[p + 9];
			p += 10;
			if (flags & 0x80)
				p += 3u * (1u << ((flags & 7) + 1));
			p += 1; // LZW minimum code size
		}
		while (p < n && g[p] != 0) // sub-blocks up to the terminator
			p += 1u + g[p];
		p += 1;
	}
	assert_true(p < n); // ends with the trailer
	return frames;
}

typedef struct picture {
	png_image image;
	png_bytep pixels; // RGB
} picture;

static picture read_png(const char *path) {
	picture pic;
	memset(&pic, 0, sizeof pic);
	pic.image.version = PNG_IMAGE_VERSION;
	assert_true(png_image_begin_read_from_file(&pic.image, path));
	pic.image.format = PNG_FORMAT_RGB;
	pic.pixels = malloc(PNG_IMAGE_SIZE(pic.image));
	assert_non_null(pic.pixels);
	assert_true(png_image_finish_read(&pic.image, NULL, pic.pixels, 0, NULL));
	return pic;
}

// Pixels in the middle half of the picture (x0 .. x0 + w of it) that are clearly blue (an object
// in no contact) or clearly orange-red (an object pushed).
static void count_colours(const picture *pic, int x0, int w, long *blue, long *orange) {
	*blue = *orange = 0;
	int W = (int)pic->image.width, H = (int)pic->image.height;
	for (int y = H / 4; y < 3 * H / 4; ++y)
		for (int x = x0 + w / 4; x < x0 + 3 * w / 4; ++x) {
			const png_byte *p = pic->pixels + 3 * ((size_t)y * (size_t)W + (size_t)x);
			if (p[2] > p[0] + 50 && p[2] > p[1])
				(*blue)++;
			if (p[0] > p[2] + 80 && p[1] > p[2] + 20 && p[0] > 150)
				(*orange)++;
		}
}

// push_press_down: a finger comes down on a box and presses it. The filmstrip at 0 and 0.6 s has
// two panels of the size asked for; in the first the box (no contact yet) is blue, in the second,
// pressed, it is orange and no blue is left: the colours follow the contact state.
static void test_strip_shows_state(void **state) {
	(void)state;
	const char *png = "build/test_view_strip.png";
	const char *args[] = {"scenarios/hand/push_press_down.yaml", "--strip", png, "--at", "0,0.6", "--size", "320x240", NULL};
	assert_int_equal(view(args), 0);
	picture pic = read_png(png);
	assert_int_equal(pic.image.width, 640);
	assert_int_equal(pic.image.height, 240);
	long blue, orange;
	count_colours(&pic, 0, 320, &blue, &orange);
	assert_true(blue > 200);
	count_colours(&pic, 320, 320, &blue, &orange);
	assert_true(orange > 200);
	assert_true(blue < 10);
	free(pic.pixels);
	png_image_free(&pic.image);
	unlink(png);
}

// A GIF of every 10th frame of a 90-frame scenario has 10 frames (0, 10, ..., 90) of the size
// asked for. The replay page is one file: titled by the scenario file, the run inside as JSON with
// the same frames (--every 10: 0, 10, ..., 90), three.js inline, no src= or href= that would load
// anything else (make check-browser drives the page itself in Chromium).
static void test_gif_and_html(void **state) {
	(void)state;
	const char *gif = "build/test_view.gif", *html = "build/test_view.html";
	const char *args[] = {"scenarios/hand/push_press_down.yaml", "--gif", gif, "--every", "10", "--html", html,
	                      "--size", "200x150", NULL};
	assert_int_equal(view(args), 0);
	size_t n;
	unsigned char *g = read_all(gif, &n);
	assert_non_null(g);
	int w, h;
	assert_int_equal(gif_frames(g, n, &w, &h), 10);
	assert_int_equal(w, 200);
	assert_int_equal(h, 150);
	free(g);
	char *page = (char *)read_all(html, &n);
	assert_non_null(page);
	assert_non_null(strstr(page, "<title>scenarios/hand/push_press_down.yaml"));
	assert_non_null(strstr(page, "<script type=\"application/json\" id=\"run\">{\"file\":\"scenarios/hand/push_press_down.yaml\""));
	int frames = 0;
	for (const char *p = page; (p = strstr(p, "{\"f\":")) != NULL; ++p)
		frames++;
	assert_int_equal(frames, 10);
	assert_non_null(strstr(page, "{\"f\":90,"));
	assert_non_null(strstr(page, "Copyright 2010-2026 Three.js Authors")); // three.core.min.js's header
	assert_null(strstr(page, " src=\""));
	assert_null(strstr(page, "href=\""));
	assert_null(strstr(page, "<link"));
	assert_null(strstr(page, "@@")); // every marker of the template filled
	assert_non_null(strstr(page, "</html>"));
	free(page);
	unlink(gif);
	unlink(html);
}

// Pixels of the hand's skin colours (segments #c98e6b, palm #e0b392 and their shades) and of the
// objects' contact-state colours, anywhere and in a band `edge` pixels wide along the border.
static void count_in_frame(const picture *pic, int edge, long *skin, long *skin_edge, long *object_edge) {
	*skin = *skin_edge = *object_edge = 0;
	int W = (int)pic->image.width, H = (int)pic->image.height;
	for (int y = 0; y < H; ++y)
		for (int x = 0; x < W; ++x) {
			const png_byte *p = pic->pixels + 3 * ((size_t)y * (size_t)W + (size_t)x);
			bool border = x < edge || y < edge || x >= W - edge || y >= H - edge;
			bool is_skin = p[0] > 150 && p[0] > p[1] + 25 && p[1] > p[2] + 15 && p[2] > 60;
			bool is_object = (p[2] > p[0] + 50 && p[2] > p[1]) || (p[0] > p[2] + 80 && p[1] > p[2] + 20 && p[0] > 150);
			*skin += is_skin;
			*skin_edge += is_skin && border;
			*object_edge += is_object && border;
		}
}

// Without --size a panel is 1024x768, and the frame holds the whole scene: the hand and the box
// pressed are in the picture and none of them touches its border (push_press_down at 0.6 s).
static void test_default_frame(void **state) {
	(void)state;
	const char *png = "build/test_view_frame.png";
	const char *args[] = {"scenarios/hand/push_press_down.yaml", "--strip", png, "--at", "0.6", NULL};
	assert_int_equal(view(args), 0);
	picture pic = read_png(png);
	assert_int_equal(pic.image.width, 1024);
	assert_int_equal(pic.image.height, 768);
	long skin, skin_edge, object_edge, blue, orange;
	count_in_frame(&pic, 10, &skin, &skin_edge, &object_edge);
	assert_true(skin > 2000);
	assert_int_equal(skin_edge, 0);
	assert_int_equal(object_edge, 0);
	count_colours(&pic, 0, 1024, &blue, &orange);
	assert_true(orange > 10000);
	free(pic.pixels);
	png_image_free(&pic.image);
	unlink(png);
}

// Bad options: exit status 2, nothing written.
static void test_bad_options(void **state) {
	(void)state;
	const char *none[] = {"scenarios/hand/push_press_down.yaml", NULL};
	assert_int_equal(view(none), 2);
	const char *no_at[] = {"scenarios/hand/push_press_down.yaml", "--strip", "build/x.png", NULL};
	assert_int_equal(view(no_at), 2);
	const char *bad_every[] = {"scenarios/hand/push_press_down.yaml", "--gif", "build/x.gif", "--every", "0", NULL};
	assert_int_equal(view(bad_every), 2);
	const char *missing[] = {"scenarios/no_such.yaml", "--gif", "build/x.gif", NULL};
	assert_int_equal(view(missing), 2);
	assert_int_equal(access("build/x.gif", F_OK), -1);
	assert_int_equal(access("build/x.png", F_OK), -1);
}

int main(void) {
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_strip_shows_state),
	    cmocka_unit_test(test_gif_and_html),
	    cmocka_unit_test(test_default_frame),
	    cmocka_unit_test(test_bad_options),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
